#include "server/bounded_http_server.h"

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace shadetree {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// Whether `socket` becomes ready for `events` within `timeout`.
bool wait_for(int socket, short events, milliseconds timeout) {
  pollfd entry{socket, events, 0};
  const Clock::time_point end = Clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::duration_cast<milliseconds>(end - Clock::now());
    const int ready = ::poll(&entry, 1, static_cast<int>(std::max<milliseconds::rep>(left.count(), 0)));
    if (ready > 0) return true;
    if (ready == 0 || errno != EINTR) return false;
  }
}

// A connection's socket as httplib reads and writes it, with the limits:
// reads fail once the request's deadline has passed, however fast bytes
// still arrive.
class LimitedSocketStream final : public httplib::Stream {
 public:
  LimitedSocketStream(int socket, const ConnectionLimits& limits) : socket_(socket), limits_(limits) {}

  void start_request() {
    deadline_ = Clock::now() + limits_.request_timeout;
    read_failed_ = false;
  }
  // Whether a read of this request failed: httplib answers 400 and would
  // read the next request from what a slow client sends next.
  bool read_failed() const { return read_failed_; }
  bool has_buffered_bytes() const { return begin_ < end_; }

  bool is_readable() const override { return has_buffered_bytes() || wait_for(socket_, POLLIN, read_time_left()); }
  bool is_writable() const override { return wait_for(socket_, POLLOUT, limits_.read_write_timeout); }

  ssize_t read(char* bytes, size_t size) override {
    if (!has_buffered_bytes()) {
      const ssize_t received = Clock::now() >= deadline_ ? -1 : retried(POLLIN, read_time_left(), [&] {
        return ::recv(socket_, buffer_, sizeof buffer_, MSG_DONTWAIT);
      });
      if (received <= 0) {
        read_failed_ = true;
        return received;
      }
      begin_ = 0;
      end_ = static_cast<size_t>(received);
    }
    const size_t copied = std::min(size, end_ - begin_);
    std::copy_n(buffer_ + begin_, copied, bytes);
    begin_ += copied;
    return static_cast<ssize_t>(copied);
  }

  ssize_t write(const char* bytes, size_t size) override {
    return retried(POLLOUT, limits_.read_write_timeout,
                   [&] { return ::send(socket_, bytes, size, MSG_DONTWAIT | MSG_NOSIGNAL); });
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override { address(::getpeername, ip, port); }
  void get_local_ip_and_port(std::string& ip, int& port) const override { address(::getsockname, ip, port); }
  socket_t socket() const override { return socket_; }

 private:
  // transfer() once the socket is ready for `events`, again if it was not
  // ready after all; -1 when it is not ready within `timeout`.
  template <typename Transfer>
  ssize_t retried(short events, milliseconds timeout, const Transfer& transfer) const {
    for (;;) {
      if (!wait_for(socket_, events, timeout)) return -1;
      const ssize_t moved = transfer();
      if (moved >= 0 || (errno != EAGAIN && errno != EINTR)) return moved;
    }
  }

  milliseconds read_time_left() const {
    const auto to_deadline = std::chrono::duration_cast<milliseconds>(deadline_ - Clock::now());
    return std::min(to_deadline, limits_.read_write_timeout);
  }

  void address(int (*name_of)(int, sockaddr*, socklen_t*), std::string& ip, int& port) const {
    sockaddr_storage storage{};
    socklen_t length = sizeof storage;
    char text[INET6_ADDRSTRLEN] = "";
    port = 0;
    if (name_of(socket_, reinterpret_cast<sockaddr*>(&storage), &length) != 0) return;
    if (storage.ss_family == AF_INET) {
      const auto* v4 = reinterpret_cast<const sockaddr_in*>(&storage);
      ::inet_ntop(AF_INET, &v4->sin_addr, text, sizeof text);
      port = ntohs(v4->sin_port);
    } else if (storage.ss_family == AF_INET6) {
      const auto* v6 = reinterpret_cast<const sockaddr_in6*>(&storage);
      ::inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof text);
      port = ntohs(v6->sin6_port);
    }
    ip = text;
  }

  int socket_;
  const ConnectionLimits& limits_;
  Clock::time_point deadline_ = Clock::now();
  bool read_failed_ = false;
  char buffer_[4096];
  size_t begin_ = 0, end_ = 0;
};

// Whether this thread is one of ConnectionWorkers': a connection run on
// any other (the accepting thread) is one past the cap, to be refused.
thread_local bool on_connection_worker = false;

// `workers` threads serve connections, one each at a time; up to
// `max_connections` in all are open, the rest waiting for a worker, first
// come first served. A connection past that is run at once on the
// accepting thread, which refuses it. The worker idle most recently takes
// the next connection, so a steady client is served by the same few
// threads: glibc keeps a malloc arena per thread, and rotating over 32
// workers grew the server's memory by megabytes over 1,000 edits (with
// one arena, by 24 KiB).
class ConnectionWorkers final : public httplib::TaskQueue {
 public:
  ConnectionWorkers(int workers, int max_connections)
      : workers_(static_cast<size_t>(std::max(workers, 1))),
        max_waiting_(static_cast<size_t>(std::max(max_connections - workers, 0))) {
    for (Worker& worker : workers_) {
      idle_.push_back(&worker);
      worker.thread = std::thread([this, &worker] { work(worker); });
    }
  }

  void enqueue(std::function<void()> connection) override {
    std::unique_lock lock(mutex_);
    if (!idle_.empty()) {
      Worker* worker = idle_.back();
      idle_.pop_back();
      worker->connection = std::move(connection);
      worker->wake.notify_one();
    } else if (waiting_.size() < max_waiting_) {
      waiting_.push_back(std::move(connection));
    } else {
      lock.unlock();
      connection();  // refused at once: not on a worker
    }
  }

  void shutdown() override {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    for (Worker& worker : workers_) worker.wake.notify_one();
    for (Worker& worker : workers_) worker.thread.join();
  }

 private:
  struct Worker {
    std::function<void()> connection;  // the one to serve, if any
    std::condition_variable wake;
    std::thread thread;
  };

  void work(Worker& worker) {
    on_connection_worker = true;
    std::unique_lock lock(mutex_);
    for (;;) {
      worker.wake.wait(lock, [&] { return stopping_ || worker.connection; });
      if (!worker.connection) return;
      lock.unlock();
      worker.connection();
      lock.lock();
      worker.connection = nullptr;
      if (waiting_.empty()) {
        idle_.push_back(&worker);
      } else {
        worker.connection = std::move(waiting_.front());
        waiting_.pop_front();
      }
    }
  }

  std::mutex mutex_;
  std::vector<Worker> workers_;
  std::vector<Worker*> idle_;  // the most recently idle last
  std::deque<std::function<void()>> waiting_;
  size_t max_waiting_;
  bool stopping_ = false;
};

class BoundedHttpServer final : public httplib::Server {
 public:
  explicit BoundedHttpServer(const ConnectionLimits& limits) : limits_(limits) {
    new_task_queue = [limits] { return new ConnectionWorkers(limits.workers, limits.max_connections); };
  }

 private:
  // httplib's own loop over a connection's requests, with the limits.
  bool process_and_close_socket(socket_t socket) override {
    if (!on_connection_worker) return refuse(socket);
    // Replies are sent as they are written: with Nagle's algorithm, a
    // reply's last part waited for the browser's delayed acknowledgement
    // of its first (7 ms of a 15 ms preview round trip in Chromium).
    const int no_delay = 1;
    ::setsockopt(socket, IPPROTO_TCP, TCP_NODELAY, &no_delay, sizeof no_delay);
    LimitedSocketStream stream(socket, limits_);
    bool served = true;
    for (int request = 1; served && request <= limits_.keep_alive_requests; ++request) {
      if (!stream.has_buffered_bytes() && !await_request(socket)) break;
      stream.start_request();
      bool closed = false;
      served = process_request(stream, request == limits_.keep_alive_requests, closed, nullptr);
      if (closed || stream.read_failed()) break;
    }
    ::shutdown(socket, SHUT_RDWR);
    ::close(socket);
    return served;
  }

  // A one-line JSON error, as the server's others, sent without waiting.
  static bool refuse(socket_t socket) {
    static const std::string body = R"({"error": "too many connections"})";
    static const std::string response = "HTTP/1.1 503 Service Unavailable\r\nContent-Type: application/json\r\n"
                                        "Content-Length: " + std::to_string(body.size()) +
                                        "\r\nConnection: close\r\n\r\n" + body;
    ::send(socket, response.data(), response.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
    ::shutdown(socket, SHUT_RDWR);
    ::close(socket);
    return false;
  }

  // Whether a request starts within the keep-alive timeout; false at once
  // when the server stops.
  bool await_request(int socket) const {
    const Clock::time_point end = Clock::now() + limits_.keep_alive_timeout;
    while (svr_sock_ != INVALID_SOCKET) {
      const auto left = std::chrono::duration_cast<milliseconds>(end - Clock::now());
      if (left.count() <= 0) return false;
      if (wait_for(socket, POLLIN, std::min(left, milliseconds(100)))) return true;
    }
    return false;
  }

  ConnectionLimits limits_;
};

}  // namespace

std::unique_ptr<httplib::Server> make_bounded_http_server(const ConnectionLimits& limits) {
  return std::make_unique<BoundedHttpServer>(limits);
}

}  // namespace shadetree
