// An MPI job this process is a rank of. When mpirun starts shadetree (its
// environment says so), the MPI module (libshadetree_mpi.so,
// schedule/mpi_module.cpp) is loaded and the process joins the job;
// otherwise no MPI library is ever loaded, and a binary built without MPI
// says so when mpirun starts it.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "graph/diagnostic.h"
#include "schedule/image_tiles.h"

namespace shadetree {

class MpiJob {
 public:
  // Whether a launcher (Open MPI's mpirun, or one speaking PMIx) started
  // this process as a rank.
  static bool launched();
  // Joins the job; once per process. Leaving it (the destructor) is MPI_Finalize.
  static Result<std::unique_ptr<MpiJob>> join();
  ~MpiJob();
  MpiJob(const MpiJob&) = delete;
  MpiJob& operator=(const MpiJob&) = delete;

  int rank() const { return rank_; }
  int ranks() const { return ranks_; }

  // Items numbered from 0 (frames, tiles) handed to the ranks one at a
  // time as they ask (rank 0 serves them), each to one rank. Every rank
  // opens the job's queues in the same order, and closes each once it
  // claims nothing more.
  class Queue : public TileClaims {
   public:
    explicit Queue(MpiJob& job);
    ~Queue() override;
    Queue(const Queue&) = delete;
    Queue& operator=(const Queue&) = delete;
    // The next item of `count` for this rank, or -1 once none is left or a
    // rank failed. Any thread.
    long claim(long count) override;
    // This rank's tiles (when the queue hands out an image's tiles), in the
    // order they were rendered.
    void rendered(long index, const Tile& tile) override;
    std::vector<Tile> rendered_tiles() const;
    // This rank failed: no rank is handed another item.
    void fail();
    // Every rank: true when no rank failed.
    bool close();

   private:
    MpiJob& job_;
    bool closed_ = false;
    mutable std::mutex mutex_;
    std::vector<Tile> tiles_;
  };

  // Every rank's `mine`, combined the same on every rank: the largest (of
  // exit statuses, the worst) and rank 0's.
  std::pair<int, int> agree(int mine);

  // A buffer from this rank to rank 0 (not rank 0 itself) ...
  void send_to_zero(const std::vector<char>& bytes);
  // ... and on rank 0, rank `from`'s.
  std::vector<char> receive_from(int from);

 private:
  struct Module;
  MpiJob(std::unique_ptr<Module> module, int rank, int ranks);
  std::unique_ptr<Module> module_;
  int rank_ = 0, ranks_ = 1;
};

}  // namespace shadetree
