#include "udpm_bus.hpp"

#include <arpa/inet.h>
#include <linux/filter.h>
#include <netinet/in.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <deque>
#include <stdexcept>
#include <thread>
#include <unordered_set>

#include "channels.hpp"
#include "fragment_reassembly.hpp"
#include "subscribers.hpp"

namespace hil::lcm_support {
namespace {

constexpr uint32_t lcm_short = 0x4c433032;  // "LC02": one datagram
constexpr size_t short_header = 8, max_channel = 63;
constexpr size_t lcm_short_max_payload = 65499;  // name, NUL and data (LCM_SHORT_MESSAGE_MAX_SIZE)
constexpr uint32_t udp_header = 8;  // a UDP socket's filter sees the UDP header first

uint32_t be32(const uint8_t* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }

struct Group {
  in_addr address{};
  int port = 0;
  int recv_buf_size = 0;
  int ttl = 0;  // LCM's default: the datagrams stay on this machine
};

int url_option(const std::string& options, const std::string& name, int otherwise) {
  const std::string key = name + "=";
  for (size_t at = 0; at < options.size();) {
    const size_t end = std::min(options.find('&', at), options.size());
    if (options.compare(at, key.size(), key) == 0) return std::atoi(options.c_str() + at + key.size());
    at = end + 1;
  }
  return otherwise;
}

Group parse_url(const std::string& url) {
  const std::string scheme = "udpm://";
  if (url.rfind(scheme, 0) != 0) throw std::runtime_error("not a udpm URL: " + url);
  const std::string rest = url.substr(scheme.size());
  const size_t query = rest.find('?');
  const std::string host_port = rest.substr(0, query);
  const size_t colon = host_port.find(':');
  Group g;
  if (colon == std::string::npos || inet_pton(AF_INET, host_port.substr(0, colon).c_str(), &g.address) != 1)
    throw std::runtime_error("no multicast group:port in " + url);
  try {
    g.port = std::stoi(host_port.substr(colon + 1));
  } catch (const std::exception&) {
    throw std::runtime_error("no port in " + url);
  }
  if (query != std::string::npos) {
    const std::string options = rest.substr(query + 1);
    g.recv_buf_size = url_option(options, "recv_buf_size", 0);
    g.ttl = url_option(options, "ttl", 0);
  }
  return g;
}

class UdpmBus : public Bus {
 public:
  UdpmBus(const std::string& url, UdpmReceive receive) : sender_(url), receive_(receive) {
    if (!sender_.good()) throw std::runtime_error("cannot open LCM on " + url);
    if (receive_.batch.count() > 0) prctl(PR_SET_TIMERSLACK, 1000UL);  // 1 us: the pause as asked, not 50 us later
    const Group group = parse_url(url);
    open_sender(group);
    fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
    const int one = 1;
    setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);  // as LCM's own receivers on the port
    if (group.recv_buf_size > 0 &&
        setsockopt(fd_, SOL_SOCKET, SO_RCVBUFFORCE, &group.recv_buf_size, sizeof group.recv_buf_size) != 0)
      setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &group.recv_buf_size, sizeof group.recv_buf_size);
    sockaddr_in any{};
    any.sin_family = AF_INET;
    any.sin_addr.s_addr = htonl(INADDR_ANY);
    any.sin_port = htons(static_cast<uint16_t>(group.port));
    ip_mreq membership{};
    membership.imr_multiaddr = group.address;
    membership.imr_interface.s_addr = htonl(INADDR_ANY);
    if (bind(fd_, reinterpret_cast<sockaddr*>(&any), sizeof any) != 0 ||
        setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0) {
      const std::string what = std::strerror(errno);
      close(fd_);
      throw std::runtime_error("cannot receive on " + url + ": " + what +
                               " (no multicast route? see README: scripts/in_netns.sh)");
    }
  }
  ~UdpmBus() override {
    try {
      flush();
    } catch (const std::exception&) {  // a node that ends cannot do more about it
    }
    close(fd_);
    close(send_fd_);
  }

  // Held until the node next waits (handle_timeout), then sent together in
  // one system call: the receivers woken by a cycle's messages then run
  // after the sender has sent them all, not one by one in between.
  void publish(const std::string& channel, const void* data, uint32_t size) override {
    const size_t datagram = short_header + channel.size() + 1 + size;
    if (channel.size() > max_channel || channel.size() + 1 + size > lcm_short_max_payload) {
      flush();  // in order; LCM itself fragments a long message (and refuses a long name)
      if (sender_.publish(channel, data, size) != 0) throw std::runtime_error("LCM publish on " + channel + " failed");
      return;
    }
    if (queued_ == outgoing_.size()) outgoing_.emplace_back();
    std::vector<uint8_t>& d = outgoing_[queued_++];
    d.resize(datagram);
    const uint32_t header[2] = {htonl(lcm_short), htonl(seqno_++)};
    std::memcpy(d.data(), header, short_header);
    std::memcpy(d.data() + short_header, channel.c_str(), channel.size() + 1);
    if (size > 0) std::memcpy(d.data() + short_header + channel.size() + 1, data, size);
  }

  int subscribe(const std::string& channel, Handler handler, int) override {
    const int id = subscribers_.add(channel, std::move(handler));
    refilter();
    return id;
  }

  void unsubscribe(int id) override {
    subscribers_.remove(id);
    refilter();
  }

  int handle_timeout(int timeout_ms) override {
    flush();
    if (pending_.empty()) {
      if (receive_.batch.count() > 0) {
        std::this_thread::sleep_for(std::min<std::chrono::microseconds>(receive_.batch, std::chrono::milliseconds(timeout_ms)));
        if (read_available(0) < 0) return -1;
      } else if (read_available(timeout_ms) < 0) {
        return -1;
      }
    }
    if (pending_.empty()) return 0;
    Message m = std::move(pending_.front());
    pending_.pop_front();
    const lcm::ReceiveBuffer rbuf{m.bytes.data(), m.malformed ? static_cast<uint32_t>(-1) : static_cast<uint32_t>(m.bytes.size()),
                                  m.recv_utime};
    subscribers_.dispatch(rbuf, m.channel);
    return 1;
  }

  traffic::Ledger refused() const override { return reassembly_.refused(); }

 private:
  struct Message {
    std::string channel;
    std::vector<uint8_t> bytes;
    int64_t recv_utime;
    bool malformed = false;  // no channel name: only for subscribers of every channel
  };

  void open_sender(const Group& group) {
    send_fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (send_fd_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
    const unsigned char ttl = static_cast<unsigned char>(group.ttl), loop = 1;
    if (setsockopt(send_fd_, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl) != 0 ||
        setsockopt(send_fd_, IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop) != 0)
      throw std::runtime_error(std::string("multicast options: ") + std::strerror(errno));
    sockaddr_in destination{};
    destination.sin_family = AF_INET;
    destination.sin_addr = group.address;
    destination.sin_port = htons(static_cast<uint16_t>(group.port));
    // Connected: no route lookup per datagram (~0.9 of ~4.5 us a send here).
    if (connect(send_fd_, reinterpret_cast<sockaddr*>(&destination), sizeof destination) != 0)
      throw std::runtime_error(std::string("cannot send to the group: ") + std::strerror(errno));
  }

  void flush() {
    if (queued_ == 0) return;
    std::vector<mmsghdr> headers(queued_);
    std::vector<iovec> io(queued_);
    for (size_t i = 0; i < queued_; ++i) {
      io[i] = {outgoing_[i].data(), outgoing_[i].size()};
      headers[i].msg_hdr.msg_iov = &io[i];
      headers[i].msg_hdr.msg_iovlen = 1;
    }
    for (size_t sent = 0; sent < queued_;) {
      const int n = sendmmsg(send_fd_, headers.data() + sent, static_cast<unsigned>(queued_ - sent), 0);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        queued_ = 0;
        throw std::runtime_error(std::string("LCM publish failed: ") + std::strerror(errno));
      }
      sent += static_cast<size_t>(n);
    }
    queued_ = 0;
  }

  void refilter() {
    bool every = false;
    const std::vector<std::string> names = subscribers_.names(every);
    every_ = every;
    named_ = {names.begin(), names.end()};
    // A subscriber of every channel gets every datagram, and none is dropped
    // by a filter: the logger counts the kernel's drops at its socket, and a
    // filter's count there too.
    const std::vector<FilterInstruction> program = every ? std::vector<FilterInstruction>{} : channel_filter(names);
    if (program.empty()) {
      const int unused = 0;
      setsockopt(fd_, SOL_SOCKET, SO_DETACH_FILTER, &unused, sizeof unused);
      return;
    }
    std::vector<sock_filter> code;
    for (const FilterInstruction& i : program) code.push_back({i.code, i.jt, i.jf, i.k});
    sock_fprog fprog{static_cast<unsigned short>(code.size()), code.data()};
    if (setsockopt(fd_, SOL_SOCKET, SO_ATTACH_FILTER, &fprog, sizeof fprog) != 0)
      throw std::runtime_error(std::string("SO_ATTACH_FILTER: ") + std::strerror(errno));
  }

  // Blocks on the socket itself (no poll before: one system call less per
  // wake-up) until one datagram is there or `timeout_ms` has passed, then
  // reads every datagram waiting, many per system call.
  int read_available(int timeout_ms) {
    if (timeout_ms != receive_timeout_ms_) {
      const timeval t{timeout_ms / 1000, (timeout_ms % 1000) * 1000};
      if (setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &t, sizeof t) != 0) return -1;
      receive_timeout_ms_ = timeout_ms;
    }
    int flags = timeout_ms > 0 ? MSG_WAITFORONE : MSG_DONTWAIT;
    constexpr unsigned batch = 32;
    if (buffers_.empty()) buffers_.assign(batch, std::vector<uint8_t>(65536));
    for (;;) {
      mmsghdr headers[batch]{};
      iovec io[batch];
      sockaddr_in from[batch];
      for (unsigned i = 0; i < batch; ++i) {
        io[i] = {buffers_[i].data(), buffers_[i].size()};
        headers[i].msg_hdr.msg_iov = &io[i];
        headers[i].msg_hdr.msg_iovlen = 1;
        headers[i].msg_hdr.msg_name = &from[i];
        headers[i].msg_hdr.msg_namelen = sizeof from[i];
      }
      const int n = recvmmsg(fd_, headers, batch, flags, nullptr);
      if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR ? 0 : -1;
      flags = MSG_DONTWAIT;
      const int64_t now = wall_clock_us();
      for (int i = 0; i < n; ++i) take(buffers_[i].data(), headers[i].msg_len, from[i], now);
      reassembly_.drop_stale(now);  // partial messages no fragment came for, even if no fragment comes
      if (n < static_cast<int>(batch)) return 0;
    }
  }

  // LCM's datagram formats (lcm/udpm_util.h of LCM 1.3.1); a fragment goes
  // to the reassembly, which holds only what arrived, within its caps.
  void take(const uint8_t* d, size_t size, const sockaddr_in& from, int64_t now) {
    if (size < short_header) return;
    const uint32_t magic = be32(d);
    if (magic == lcm_short) {
      const auto* name = d + short_header;
      const auto* nul = static_cast<const uint8_t*>(std::memchr(name, 0, std::min(size - short_header, max_channel + 1)));
      if (!nul) return pending_.push_back({"", {}, now, true});
      pending_.push_back({std::string(reinterpret_cast<const char*>(name), nul - name),
                          std::vector<uint8_t>(nul + 1, d + size), now});
      return;
    }
    if (magic != lcm_fragment_magic) return;
    if (auto m = reassembly_.take(d, size, {from.sin_addr.s_addr, from.sin_port}, now))
      pending_.push_back({std::move(m->channel), std::move(m->bytes), now, !m->framed});
  }

  // Whether a message on `channel` has a subscriber here (as Subscribers hands it on).
  bool wanted(const std::string& channel) const {
    return every_ ? channel != channels::lcm_self_test : named_.count(channel) > 0;
  }

  lcm::LCM sender_;
  UdpmReceive receive_;
  int fd_ = -1;
  int send_fd_ = -1;
  int receive_timeout_ms_ = 0;  // SO_RCVTIMEO now; 0: none
  uint32_t seqno_ = 0;
  std::vector<std::vector<uint8_t>> outgoing_;  // [0, queued_): to send; reused
  size_t queued_ = 0;
  Subscribers subscribers_;
  std::deque<Message> pending_;
  bool every_ = false;  // as subscribed (refilter)
  std::unordered_set<std::string> named_;
  FragmentReassembly reassembly_{[this](const std::string& channel) { return wanted(channel); }};
  std::vector<std::vector<uint8_t>> buffers_;
};

}  // namespace

std::vector<FilterInstruction> channel_filter(const std::vector<std::string>& channels) {
  constexpr uint16_t load_word = BPF_LD | BPF_W | BPF_ABS, load_half = BPF_LD | BPF_H | BPF_ABS,
                     load_byte = BPF_LD | BPF_B | BPF_ABS, equal = BPF_JMP | BPF_JEQ | BPF_K, ret = BPF_RET | BPF_K;
  constexpr uint32_t accept = 0xFFFFFFFF, drop = 0;
  std::vector<FilterInstruction> p{{load_word, 0, 0, udp_header}, {equal, 1, 0, lcm_short}, {ret, 0, 0, drop}};
  for (const std::string& channel : channels) {
    if (channel.size() > max_channel) return {};
    const std::string name = channel + '\0';  // the name ends with its NUL
    std::vector<FilterInstruction> block;
    for (size_t at = 0; at < name.size();) {
      const size_t left = name.size() - at;
      const size_t width = left >= 4 ? 4 : left >= 2 ? 2 : 1;
      uint32_t value = 0;
      for (size_t i = 0; i < width; ++i) value = value << 8 | static_cast<uint8_t>(name[at + i]);
      const auto offset = static_cast<uint32_t>(udp_header + short_header + at);
      block.push_back({width == 4 ? load_word : width == 2 ? load_half : load_byte, 0, 0, offset});
      block.push_back({equal, 0, 0, value});
      at += width;
    }
    block.push_back({ret, 0, 0, accept});
    for (size_t i = 1; i < block.size(); i += 2)  // a mismatch goes on with the next channel
      block[i].jf = static_cast<uint8_t>(block.size() - i - 1);
    p.insert(p.end(), block.begin(), block.end());
  }
  p.push_back({ret, 0, 0, drop});
  return p;
}

std::unique_ptr<Bus> udpm_bus(const std::string& url, UdpmReceive receive) {
  return std::make_unique<UdpmBus>(url, receive);
}

std::unique_ptr<Bus> node_bus(const std::string& url, UdpmReceive receive) {
  return url.rfind("udpm://", 0) == 0 ? udpm_bus(url, receive) : lcm_bus(url);
}

}  // namespace hil::lcm_support
