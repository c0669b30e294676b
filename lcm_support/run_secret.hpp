#pragma once
// RIG-12: a run's secret and the MAC every message of the run carries, so
// that traffic not from the run's own processes is refused whatever run id
// it claims. `hil run` draws the secret and writes it into the run folder
// (mode 0600); each node reads it from there, never from the bus or its
// command line (which every user of the host can read).
//
// The MAC is libsodium's crypto_shorthash (SipHash-2-4, 64 bits) under a
// key per channel (BLAKE2b of the channel name keyed with the secret:
// crypto_generichash), over every byte of the encoded message before its
// last field, `int64_t mac`, which it fills. A message is thereby bound to
// its channel: AXIS_X_STATE's bytes are not a valid AXIS_Y_STATE.
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

namespace hil::lcm_support {

class RunSecret {
 public:
  static constexpr size_t key_bytes = 16;
  static constexpr size_t mac_bytes = 8;

  // A fresh secret from the system's random source.
  static RunSecret generate();
  // Reads a secret file; throws naming it if it is missing, not 16 bytes,
  // or readable by others than its owner.
  static RunSecret read(const std::string& path);
  // Creates `path` (mode 0600, it must not exist yet) holding the secret.
  void write(const std::string& path) const;

  // Fills the last 8 bytes of an encoded rig message on `channel` with its
  // MAC; false (nothing changed) for fewer bytes than a MAC.
  bool sign(const std::string& channel, uint8_t* data, size_t size) const;
  // Whether the last 8 bytes are the MAC of the rest on `channel`.
  bool verify(const std::string& channel, const uint8_t* data, size_t size) const;

 private:
  explicit RunSecret(const std::array<uint8_t, key_bytes>& key);
  using Key = std::array<uint8_t, key_bytes>;
  Key channel_key(const std::string& channel) const;
  uint64_t mac(const std::string& channel, const uint8_t* data, size_t size) const;

  Key key_;
  // The rig's own channels, derived once; invented names are derived
  // each time (a flood of them must not grow this).
  mutable std::map<std::string, Key> channel_keys_;
};

}  // namespace hil::lcm_support
