// The MPI side of distributed renders, built as a loadable module
// (libshadetree_mpi.so) so that shadetree starts without any MPI library
// and loads Open MPI only when mpirun started it (schedule/mpi_job.cpp
// holds the C++ side). A small C interface:
//
// - a work queue of numbered items (the frames of a sequence, the tiles of
//   a frame), served by a thread of rank 0 from which any thread of any
//   rank claims the next item when it is done with one, so that fast
//   ranks take more (dynamic scheduling, not an even split);
// - agreeing on a status, and sending a buffer to rank 0.
//
// Only one thread of a process calls MPI at a time (MPI_THREAD_SERIALIZED):
// on rank 0 the server thread while a queue is open and the main thread
// otherwise; on the other ranks, whichever thread holds `mpi_mutex`.
#include <dlfcn.h>
#include <mpi.h>
#include <sys/prctl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>
#include <utility>

namespace {

enum Tag : int { claim_tag = 1, reply_tag, fail_tag, done_tag, data_tag };

int rank = 0, ranks = 1;
std::mutex mpi_mutex;

// The queue's state. On rank 0 the server's; elsewhere `stopped` (this
// rank failed, so it claims nothing more) and the batch of items handed
// to this rank that its threads have not claimed yet, [next, end).
struct Queue {
  std::mutex mutex;
  long next = 0, end = 0;
  bool stopped = false;
  int done_ranks = 0;
  bool all_ok = true;
  std::thread server;
} queue;

// The next items of `count` on rank 0's queue, `wanted` of them or fewer:
// the first and how many (0: none is left).
std::pair<long, long> next_items(long count, long wanted) {
  const std::lock_guard<std::mutex> lock(queue.mutex);
  if (queue.stopped || queue.next >= count) return {-1, 0};
  const long first = queue.next;
  queue.next += std::min(wanted, count - first);
  return {first, queue.next - first};
}

long next_item(long count) { return next_items(count, 1).first; }

// What a claim from another rank is handed: a batch of an eighth of the
// remaining items' share per rank (guided self-scheduling, Polychronopoulos
// & Kuck 1987), so that a frame's 65536 tiles over 64 ranks cost some
// thousands of messages rather than 65536, while the batches near the end,
// of one item, still balance the ranks.
std::pair<long, long> next_batch(long count) {
  long remaining = 0;
  {
    const std::lock_guard<std::mutex> lock(queue.mutex);
    remaining = count - queue.next;
  }
  return next_items(count, std::max(1L, remaining / (8L * ranks)));
}

void mark_done(bool ok) {
  const std::lock_guard<std::mutex> lock(queue.mutex);
  ++queue.done_ranks;
  if (!ok) queue.all_ok = false, queue.stopped = true;
}

// Rank 0's server: answers claims until every rank has said it is done.
// It polls rather than blocking in MPI_Recv, which would spin a core that
// rank 0's own threads render on: every 10 µs while claims come (a tile
// can take a tenth of a millisecond), backing off to every millisecond
// while none do (a frame takes seconds). Polling every 50 µs throughout
// cost a 2-core machine a fifth of its render time.
void serve() {
  ::prctl(PR_SET_TIMERSLACK, 1000UL);  // nanoseconds: sleeps as short as asked
  constexpr auto fastest = std::chrono::microseconds(10), slowest = std::chrono::microseconds(1000);
  auto pause = fastest;
  for (;;) {
    {
      const std::lock_guard<std::mutex> lock(queue.mutex);
      if (queue.done_ranks == ranks) return;
    }
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) {
      std::this_thread::sleep_for(pause);
      pause = std::min(2 * pause, slowest);
      continue;
    }
    pause = fastest;
    long value = 0;
    MPI_Recv(&value, 1, MPI_LONG, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (status.MPI_TAG == claim_tag) {
      const auto [first, items] = next_batch(value);
      const long batch[2] = {first, items};
      MPI_Send(batch, 2, MPI_LONG, status.MPI_SOURCE, reply_tag, MPI_COMM_WORLD);
    } else if (status.MPI_TAG == fail_tag) {
      const std::lock_guard<std::mutex> lock(queue.mutex);
      queue.stopped = true;
    } else if (status.MPI_TAG == done_tag) {
      mark_done(value != 0);
    }
  }
}

void set_error(char* error, std::size_t size, const char* what, int code) {
  char reason[MPI_MAX_ERROR_STRING] = "";
  int length = 0;
  MPI_Error_string(code, reason, &length);
  std::snprintf(error, size, "%s: %s", what, reason);
}

}  // namespace

// Joins the job: 0 and this process's rank and the job's size, or 1 and
// why not.
extern "C" int shadetree_mpi_start(int* rank_out, int* ranks_out, char* error, std::size_t error_size) {
  // Open MPI's components are libraries it opens itself, which look for
  // its symbols globally: this module was opened with RTLD_LOCAL.
  if (!::dlopen("libmpi.so.40", RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD)) {
    std::snprintf(error, error_size, "cannot make Open MPI's symbols global: %s", ::dlerror());
    return 1;
  }
  int provided = 0;
  if (const int code = MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided); code != MPI_SUCCESS) {
    set_error(error, error_size, "MPI_Init_thread failed", code);
    return 1;
  }
  if (provided < MPI_THREAD_SERIALIZED) {
    std::snprintf(error, error_size, "this MPI library cannot be called from more than one thread");
    MPI_Finalize();
    return 1;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  *rank_out = rank;
  *ranks_out = ranks;
  return 0;
}

extern "C" void shadetree_mpi_stop() { MPI_Finalize(); }

// Opens a queue (every rank, in the same order): rank 0 starts serving.
extern "C" void shadetree_mpi_queue_open() {
  queue.next = queue.end = 0;
  queue.stopped = false;
  queue.done_ranks = 0;
  queue.all_ok = true;
  if (rank == 0 && ranks > 1) queue.server = std::thread(serve);
}

// The next item of `count` for this rank, or -1 once none is left or a
// rank failed. Any thread.
extern "C" long shadetree_mpi_queue_claim(long count) {
  if (rank == 0) return next_item(count);
  const std::lock_guard<std::mutex> lock(mpi_mutex);
  if (queue.stopped) return -1;
  if (queue.next < queue.end) return queue.next++;
  long batch[2] = {-1, 0};
  MPI_Send(&count, 1, MPI_LONG, 0, claim_tag, MPI_COMM_WORLD);
  MPI_Recv(batch, 2, MPI_LONG, 0, reply_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (batch[1] == 0) return -1;
  queue.next = batch[0] + 1;
  queue.end = batch[0] + batch[1];
  return batch[0];
}

// This rank failed: no rank is handed another item.
extern "C" void shadetree_mpi_queue_fail() {
  if (rank == 0) {
    const std::lock_guard<std::mutex> lock(queue.mutex);
    queue.stopped = true;
    queue.all_ok = false;
    return;
  }
  const std::lock_guard<std::mutex> lock(mpi_mutex);
  if (queue.stopped) return;
  queue.stopped = true;
  const long nothing = 0;
  MPI_Send(&nothing, 1, MPI_LONG, 0, fail_tag, MPI_COMM_WORLD);
}

// Closes the queue (every rank, once its threads claim no more): 1 when
// no rank failed.
extern "C" int shadetree_mpi_queue_close() {
  int ok = 1;
  if (rank == 0) {
    mark_done(true);
    if (queue.server.joinable()) queue.server.join();
    ok = queue.all_ok ? 1 : 0;
  } else {
    const long mine = queue.stopped ? 0 : 1;
    MPI_Send(&mine, 1, MPI_LONG, 0, done_tag, MPI_COMM_WORLD);
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return ok;
}

// Every rank's `value`, combined: the largest, and rank 0's.
extern "C" void shadetree_mpi_agree(int value, int* largest, int* rank_zero) {
  MPI_Allreduce(&value, largest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  *rank_zero = value;
  MPI_Bcast(rank_zero, 1, MPI_INT, 0, MPI_COMM_WORLD);
}

// A buffer from a rank to rank 0, in messages of at most 1 GB (MPI counts
// are ints): the sender calls send, and rank 0 receive_size and receive.
constexpr long piece = 1L << 30;

extern "C" void shadetree_mpi_send(const void* data, long bytes) {
  MPI_Send(&bytes, 1, MPI_LONG, 0, data_tag, MPI_COMM_WORLD);
  for (long sent = 0; sent < bytes; sent += piece)
    MPI_Send(static_cast<const char*>(data) + sent, static_cast<int>(std::min(piece, bytes - sent)), MPI_BYTE, 0,
             data_tag, MPI_COMM_WORLD);
}

extern "C" long shadetree_mpi_receive_size(int from) {
  long bytes = 0;
  MPI_Recv(&bytes, 1, MPI_LONG, from, data_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return bytes;
}

extern "C" void shadetree_mpi_receive(int from, void* data, long bytes) {
  for (long received = 0; received < bytes; received += piece)
    MPI_Recv(static_cast<char*>(data) + received, static_cast<int>(std::min(piece, bytes - received)), MPI_BYTE, from,
             data_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}
