// MPI transport of the sweep engine (built only when CMake finds MPI). Messages: rank 0 sends a
// run index (kRun) or kStop; a rank answers a run with its encoded RunRow (kRow) or, when the
// child that ran it died, with how it ended (kDied). Rank 0 decides retries (dispatch.cpp).
#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <thread>

#include "console/sweep/forked_workers.hpp"
#include "console/sweep/mpi_executor.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

enum Tag : int { kRun = 1, kRow = 2, kDied = 3, kStop = 4 };

void send_text(const std::string& bytes, int to, int tag) {
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

std::string receive_text(const MPI_Status& probed) {
  int n = 0;
  MPI_Get_count(&probed, MPI_BYTE, &n);
  std::string bytes(static_cast<std::size_t>(n), '\0');
  MPI_Recv(bytes.data(), n, MPI_BYTE, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return bytes;
}

// Slot 0 is rank 0's own forked worker; slot r (r >= 1) is rank r.
class MpiSlots final : public WorkerSlots {
 public:
  MpiSlots(int ranks, const RunFunction& run, bool& stopped)
      : ranks_(ranks), local_(1, run), stopped_(stopped) {}
  ~MpiSlots() override { stop_all(); }

  int count() const override { return ranks_; }

  void start(int slot, std::size_t index) override {
    if (slot == 0) return local_.start(0, index);
    const auto i = static_cast<std::uint64_t>(index);
    MPI_Send(&i, 1, MPI_UINT64_T, slot, kRun, MPI_COMM_WORLD);
  }

  Event wait(int timeout_ms) override {
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
    do {
      // The ranks' messages first, without waiting: a backlog drains at the messages' own cost,
      // not one per poll of the local worker.
      int arrived = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &st);
      if (!arrived) {
        Event local = local_.wait(1);  // short: the ranks are looked at again within 1 ms
        if (local.kind != Event::Kind::None) return local;
        continue;
      }
      const std::string bytes = receive_text(st);
      if (st.MPI_TAG == kDied) return {Event::Kind::Died, st.MPI_SOURCE, {}, bytes};
      try {
        return {Event::Kind::Done, st.MPI_SOURCE, decode_row(bytes), {}};
      } catch (const Error& e) {
        return {Event::Kind::Died,
                st.MPI_SOURCE,
                {},
                "rank " + std::to_string(st.MPI_SOURCE) + " sent a bad row (" + e.what() + ")"};
      }
    } while (std::chrono::steady_clock::now() < until);
    return {};
  }

  void stop_all() override {
    local_.stop_all();
    stop_ranks(ranks_, stopped_);
  }

  // Tells every other rank to stop, once.
  static void stop_ranks(int ranks, bool& stopped) {
    if (stopped) return;
    stopped = true;
    for (int r = 1; r < ranks; ++r) MPI_Send(nullptr, 0, MPI_BYTE, r, kStop, MPI_COMM_WORLD);
  }

 private:
  int ranks_;
  ForkedWorkers local_;
  bool& stopped_;
};

class MpiCoordinator final : public Executor {
 public:
  explicit MpiCoordinator(int ranks) : ranks_(ranks) {}
  ~MpiCoordinator() override { MpiSlots::stop_ranks(ranks_, stopped_); }  // also on errors
  std::string describe() const override {
    return "MPI, " + std::to_string(ranks_) + " rank" + (ranks_ == 1 ? "" : "s");
  }
  int workers() const override { return ranks_; }
  void execute(const std::vector<std::size_t>& todo, const RunFunction& run,
               const ExecutorEvents& events) override {
    MpiSlots slots(ranks_, run, stopped_);
    dispatch(slots, todo, events);
    slots.stop_all();
  }

 private:
  int ranks_;
  bool stopped_ = false;
};

}  // namespace

bool mpi_built() {
  return true;
}

MpiSession::MpiSession() {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

std::unique_ptr<Executor> mpi_coordinator(MpiSession& session) {
  return std::make_unique<MpiCoordinator>(session.size());
}

void mpi_worker(MpiSession&, const RunFunction& run) {
  ForkedWorkers local(1, run);
  for (;;) {
    MPI_Status st;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
    if (st.MPI_TAG != kRun) {
      receive_text(st);
      return;  // kStop
    }
    std::uint64_t index = 0;
    MPI_Recv(&index, 1, MPI_UINT64_T, 0, kRun, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    local.start(0, static_cast<std::size_t>(index));
    WorkerSlots::Event e;
    do e = local.wait(1000);
    while (e.kind == WorkerSlots::Event::Kind::None);
    if (e.kind == WorkerSlots::Event::Kind::Done)
      send_text(encode_row(e.row), 0, kRow);
    else
      send_text(e.reason, 0, kDied);
  }
}

std::string mpi_broadcast(MpiSession& session, const std::string& text) {
  std::uint64_t n = session.rank() == 0 ? text.size() : 0;
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  std::string out = session.rank() == 0 ? text : std::string(static_cast<std::size_t>(n), '\0');
  MPI_Bcast(out.data(), static_cast<int>(n), MPI_BYTE, 0, MPI_COMM_WORLD);
  return out;
}

}  // namespace stride::sweep
