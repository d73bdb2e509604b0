#pragma once
// Worker slots that are child processes of this one, each fed over its own socket pair: the
// child inherits the compiled sweep, reads a run index, answers with the encoded RunRow. A child
// that dies is noticed (EOF), reaped with its cause, and replaced when its slot is next used.
#include <sys/types.h>

#include <string>
#include <vector>

#include "console/sweep/dispatch.hpp"

namespace stride::sweep {

class ForkedWorkers final : public WorkerSlots {
 public:
  ForkedWorkers(int count, RunFunction run);
  ~ForkedWorkers() override;

  int count() const override { return static_cast<int>(workers_.size()); }
  void start(int slot, std::size_t index) override;
  Event wait(int timeout_ms) override;
  void stop_all() override;

  // The worker's pid and socket, for an MPI rank that relays a slot (-1 when not running).
  pid_t pid(int slot) const { return workers_[static_cast<std::size_t>(slot)].pid; }

 private:
  struct Worker {
    pid_t pid = -1;
    int fd = -1;
    bool busy = false;
    bool lost = false;  // the run could not be sent: report Died
  };
  void spawn(Worker& w);
  std::string end(Worker& w);  // closes, reaps; returns how the child ended

  RunFunction run_;
  std::vector<Worker> workers_;
};

// Moves all of `n` bytes through the socket, retrying short transfers and signals.
bool send_all(int fd, const char* data, std::size_t n);
bool receive_all(int fd, char* data, std::size_t n);
// A message: 4-byte little-endian length, then the bytes.
bool send_message(int fd, const std::string& bytes);
bool receive_message(int fd, std::string& bytes);

}  // namespace stride::sweep
