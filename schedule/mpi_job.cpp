#include "schedule/mpi_job.h"

#include <cstdlib>

#include "platform/loadable_module.h"

namespace shadetree {

struct MpiJob::Module {
  LoadableModule module{"libshadetree_mpi.so", "MPI support"};
  int (*start)(int*, int*, char*, std::size_t) = module.function<int(int*, int*, char*, std::size_t)>("shadetree_mpi_start");
  void (*stop)() = module.function<void()>("shadetree_mpi_stop");
  void (*queue_open)() = module.function<void()>("shadetree_mpi_queue_open");
  long (*queue_claim)(long) = module.function<long(long)>("shadetree_mpi_queue_claim");
  void (*queue_fail)() = module.function<void()>("shadetree_mpi_queue_fail");
  int (*queue_close)() = module.function<int()>("shadetree_mpi_queue_close");
  void (*agree)(int, int*, int*) = module.function<void(int, int*, int*)>("shadetree_mpi_agree");
  void (*send)(const void*, long) = module.function<void(const void*, long)>("shadetree_mpi_send");
  long (*receive_size)(int) = module.function<long(int)>("shadetree_mpi_receive_size");
  void (*receive)(int, void*, long) = module.function<void(int, void*, long)>("shadetree_mpi_receive");
};

bool MpiJob::launched() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

Result<std::unique_ptr<MpiJob>> MpiJob::join() {
  auto module = std::make_unique<Module>();
  if (!module->module.error().empty())
    return failure(module->module.error() + ": this shadetree cannot render under mpirun");
  int rank = 0, ranks = 1;
  char error[512] = "";
  if (module->start(&rank, &ranks, error, sizeof error) != 0) return failure(std::string("cannot join the MPI job: ") + error);
  return std::unique_ptr<MpiJob>(new MpiJob(std::move(module), rank, ranks));
}

MpiJob::MpiJob(std::unique_ptr<Module> module, int rank, int ranks)
    : module_(std::move(module)), rank_(rank), ranks_(ranks) {}

MpiJob::~MpiJob() { module_->stop(); }

MpiJob::Queue::Queue(MpiJob& job) : job_(job) { job_.module_->queue_open(); }

MpiJob::Queue::~Queue() {
  if (!closed_) close();
}

long MpiJob::Queue::claim(long count) { return job_.module_->queue_claim(count); }

void MpiJob::Queue::rendered(long, const Tile& tile) {
  const std::lock_guard<std::mutex> lock(mutex_);
  tiles_.push_back(tile);
}

std::vector<Tile> MpiJob::Queue::rendered_tiles() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return tiles_;
}

void MpiJob::Queue::fail() { job_.module_->queue_fail(); }

bool MpiJob::Queue::close() {
  closed_ = true;
  return job_.module_->queue_close() != 0;
}

std::pair<int, int> MpiJob::agree(int mine) {
  int largest = 0, rank_zero = 0;
  module_->agree(mine, &largest, &rank_zero);
  return {largest, rank_zero};
}

void MpiJob::send_to_zero(const std::vector<char>& bytes) {
  module_->send(bytes.data(), static_cast<long>(bytes.size()));
}

std::vector<char> MpiJob::receive_from(int from) {
  std::vector<char> bytes(static_cast<std::size_t>(module_->receive_size(from)));
  module_->receive(from, bytes.data(), static_cast<long>(bytes.size()));
  return bytes;
}

}  // namespace shadetree
