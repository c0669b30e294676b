#include "run_secret.hpp"

#include <fcntl.h>
#include <sodium.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace hil::lcm_support {
namespace {

constexpr size_t cached_channels = 64;

void init_sodium() {
  static_assert(RunSecret::key_bytes == crypto_shorthash_KEYBYTES && RunSecret::key_bytes >= crypto_generichash_KEYBYTES_MIN);
  static_assert(RunSecret::mac_bytes == crypto_shorthash_BYTES);
  if (sodium_init() < 0) throw std::runtime_error("libsodium could not be initialised");
}

std::runtime_error file_error(const std::string& path, const std::string& what) {
  return std::runtime_error("run secret " + path + ": " + what);
}

}  // namespace

RunSecret::RunSecret(const Key& key) : key_(key) { init_sodium(); }

RunSecret RunSecret::generate() {
  init_sodium();
  Key key;
  randombytes_buf(key.data(), key.size());
  return RunSecret(key);
}

RunSecret RunSecret::read(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw file_error(path, std::strerror(errno));
  struct stat st {};
  Key key;
  const bool stated = ::fstat(fd, &st) == 0;
  const ssize_t got = ::read(fd, key.data(), key.size());
  char more = 0;
  const ssize_t extra = ::read(fd, &more, 1);
  ::close(fd);
  if (!stated) throw file_error(path, "cannot stat it");
  if ((st.st_mode & 077) != 0) throw file_error(path, "readable by others than its owner (mode must be 0600)");
  if (got != static_cast<ssize_t>(key.size()) || extra != 0)
    throw file_error(path, "not a secret of " + std::to_string(key_bytes) + " bytes");
  return RunSecret(key);
}

void RunSecret::write(const std::string& path) const {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) throw file_error(path, std::strerror(errno));
  const ssize_t put = ::write(fd, key_.data(), key_.size());
  const bool closed = ::close(fd) == 0;
  if (put != static_cast<ssize_t>(key_.size()) || !closed) throw file_error(path, "could not be written");
}

RunSecret::Key RunSecret::channel_key(const std::string& channel) const {
  if (const auto found = channel_keys_.find(channel); found != channel_keys_.end()) return found->second;
  Key k;
  crypto_generichash(k.data(), k.size(), reinterpret_cast<const unsigned char*>(channel.data()), channel.size(),
                     key_.data(), key_.size());
  if (channel_keys_.size() < cached_channels) channel_keys_.emplace(channel, k);
  return k;
}

uint64_t RunSecret::mac(const std::string& channel, const uint8_t* data, size_t size) const {
  const Key k = channel_key(channel);
  uint64_t out = 0;
  crypto_shorthash(reinterpret_cast<unsigned char*>(&out), data, size - mac_bytes, k.data());
  return out;
}

bool RunSecret::sign(const std::string& channel, uint8_t* data, size_t size) const {
  if (size < mac_bytes) return false;
  const uint64_t m = mac(channel, data, size);
  std::memcpy(data + size - mac_bytes, &m, mac_bytes);
  return true;
}

bool RunSecret::verify(const std::string& channel, const uint8_t* data, size_t size) const {
  if (size < mac_bytes) return false;
  const uint64_t m = mac(channel, data, size);
  return sodium_memcmp(&m, data + size - mac_bytes, mac_bytes) == 0;
}

}  // namespace hil::lcm_support
