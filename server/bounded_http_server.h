// The editor server's HTTP server: cpp-httplib's, with bounds on what a
// client can hold. A connection has a worker thread of its own for as long
// as it is open, so a client that keeps connections open but sends slowly
// holds workers: ten connections that each sent a header line every 2 s
// blocked every other client (slowloris, issue 21), since httplib times
// out each read, not a request. Here a request, headers and body, must
// arrive whole within a deadline from its first byte; each read and write
// has a timeout; an idle connection closes, and one serves a bounded
// number of requests. Connections past the workers wait for one, first
// come first served; past max_connections, they get a 503 and are closed.
#pragma once

#include <chrono>
#include <memory>

namespace httplib {
class Server;
}

namespace shadetree {

struct ConnectionLimits {
  // Connections served at once, each by a worker thread of its own (a
  // browser opens up to 6 to one server), and open at once, served or
  // waiting for a worker.
  int workers = 32;
  int max_connections = 256;
  // For a request's headers and body to arrive, from its first byte (the
  // editor's largest, a 4 MiB graph, takes milliseconds over loopback).
  std::chrono::milliseconds request_timeout{10000};
  // For each read and each write of a connection to make progress.
  std::chrono::milliseconds read_write_timeout{5000};
  // For the next request of a connection kept alive, or the first of a new
  // one, to start.
  std::chrono::milliseconds keep_alive_timeout{5000};
  int keep_alive_requests = 5;  // per connection, then it closes
};

// An httplib server (routes are added as usual) that holds to `limits`.
std::unique_ptr<httplib::Server> make_bounded_http_server(const ConnectionLimits& limits);

}  // namespace shadetree
