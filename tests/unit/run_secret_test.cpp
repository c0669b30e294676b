// RIG-12: the run's secret, the MAC on every message, and the bus that
// signs what a node sends and refuses what claims its run without the MAC.
#include <hil/axis_state_t.hpp>
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "authenticated_bus.hpp"
#include "channels.hpp"
#include "in_process_bus.hpp"
#include "inbox.hpp"
#include "run_secret.hpp"

using namespace hil;
using lcm_support::RunSecret;

namespace {

hil::axis_state_t state_of(int64_t run_id, int64_t cycle) {
  hil::axis_state_t m{};
  m.run_id = run_id;
  m.cycle = cycle;
  m.axis = "X";
  m.position = 12.5;
  m.mac = 0x1234;  // whatever a node leaves in it: encoded as 0, then signed
  return m;
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("hil_run_secret_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("RIG-12 run secret: the MAC binds every byte and the channel to the run's secret", "[RIG-12]") {
  const RunSecret secret = RunSecret::generate();
  std::vector<uint8_t> bytes = lcm_support::encode(state_of(7, 3));
  CHECK(std::vector<uint8_t>(bytes.end() - 8, bytes.end()) == std::vector<uint8_t>(8, 0));
  REQUIRE(secret.sign("AXIS_X_STATE", bytes.data(), bytes.size()));
  CHECK(secret.verify("AXIS_X_STATE", bytes.data(), bytes.size()));
  CHECK_FALSE(secret.verify("AXIS_Y_STATE", bytes.data(), bytes.size()));       // bound to its channel
  CHECK_FALSE(RunSecret::generate().verify("AXIS_X_STATE", bytes.data(), bytes.size()));  // another run's secret
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::vector<uint8_t> flipped = bytes;
    flipped[i] ^= 0x01;
    CHECK_FALSE(secret.verify("AXIS_X_STATE", flipped.data(), flipped.size()));
  }
  CHECK_FALSE(secret.verify("AXIS_X_STATE", bytes.data(), bytes.size() - 1));  // cut short
  CHECK_FALSE(secret.verify("AXIS_X_STATE", bytes.data(), 7));
  // lcm-spy still decodes it: the MAC is one more field
  hil::axis_state_t decoded;
  REQUIRE(lcm_support::decode(bytes.data(), static_cast<uint32_t>(bytes.size()), decoded));
  CHECK(decoded.position == 12.5);
  CHECK(decoded.mac != 0);
}

TEST_CASE("RIG-12 run secret: written once with mode 0600, read back; a file others can read is refused",
          "[RIG-12]") {
  const auto dir = fresh_dir("file");
  const std::string path = (dir / "run.key").string();
  const RunSecret secret = RunSecret::generate();
  secret.write(path);
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0600);
  CHECK(std::filesystem::file_size(path) == RunSecret::key_bytes);
  CHECK_THROWS_WITH(secret.write(path), Catch::Contains("File exists"));  // never overwritten
  std::vector<uint8_t> bytes = lcm_support::encode(state_of(7, 3));
  secret.sign("AXIS_X_STATE", bytes.data(), bytes.size());
  CHECK(RunSecret::read(path).verify("AXIS_X_STATE", bytes.data(), bytes.size()));

  ::chmod(path.c_str(), 0644);
  CHECK_THROWS_WITH(RunSecret::read(path), Catch::Contains("readable by others"));
  const std::string short_file = (dir / "short.key").string();
  std::ofstream(short_file) << "0123456789";
  ::chmod(short_file.c_str(), 0600);
  CHECK_THROWS_WITH(RunSecret::read(short_file), Catch::Contains("not a secret of 16 bytes"));
  CHECK_THROWS_WITH(RunSecret::read((dir / "none.key").string()), Catch::Contains("No such file"));
}

TEST_CASE("RIG-12 authenticated bus: signed messages of the run are taken, forged ones refused and counted, another "
          "run's counted as foreign",
          "[RIG-12]") {
  auto inner = std::make_unique<lcm_support::InProcessBus>();
  lcm_support::InProcessBus& wire = *inner;
  lcm_support::AuthenticatedBus bus(std::move(inner), RunSecret::generate(), 7);
  lcm_support::Bus& signing = bus;  // the node's side
  lcm_support::Bus& raw = wire;     // anyone else on the bus
  lcm_support::Inbox inbox(bus, 7);
  std::vector<int64_t> taken;
  inbox.on<hil::axis_state_t>("AXIS_X_STATE", [&](const hil::axis_state_t& m, const lcm::ReceiveBuffer&) {
    taken.push_back(m.cycle);
    return true;
  });
  signing.publish("AXIS_X_STATE", state_of(7, 1));  // from a process of the run
  raw.publish("AXIS_X_STATE", state_of(7, 2));      // right run id, no MAC
  raw.publish("AXIS_X_STATE", state_of(8, 3));      // another run
  std::vector<uint8_t> replayed = lcm_support::encode(state_of(7, 4));
  RunSecret::generate().sign("AXIS_X_STATE", replayed.data(), replayed.size());  // another run's secret
  raw.publish("AXIS_X_STATE", replayed.data(), static_cast<uint32_t>(replayed.size()));
  wire.drain();
  CHECK(taken == std::vector<int64_t>{1});
  const traffic::Ledger ledger = inbox.ledger();  // merged anew on each call: keep the one read
  const auto& refused = ledger.by_channel().at("AXIS_X_STATE");
  CHECK(refused.unauthenticated == 2);
  CHECK(refused.foreign_run == 1);
  CHECK_FALSE(inbox.ledger().fails_run());  // refused, not lost: the run's own traffic is all there
  CHECK(inbox.ledger().describe() == "AXIS_X_STATE: 1 foreign run, 2 unauthenticated");
}
