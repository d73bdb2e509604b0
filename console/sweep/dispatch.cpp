#include "console/sweep/dispatch.hpp"

#include <deque>
#include <map>

namespace stride::sweep {

void dispatch(WorkerSlots& slots, const std::vector<std::size_t>& todo,
              const ExecutorEvents& events) {
  using Kind = WorkerSlots::Event::Kind;
  std::deque<std::size_t> queue(todo.begin(), todo.end());
  std::vector<long long> busy(static_cast<std::size_t>(slots.count()), -1);  // run index per slot
  std::map<std::size_t, int> deaths;  // runs whose worker died under them
  std::size_t in_flight = 0;
  for (;;) {
    if (events.stop && events.stop()) {
      slots.stop_all();
      return;
    }
    for (std::size_t s = 0; s < busy.size() && !queue.empty(); ++s) {
      if (busy[s] >= 0) continue;
      busy[s] = static_cast<long long>(queue.front());
      queue.pop_front();
      ++in_flight;
      slots.start(static_cast<int>(s), static_cast<std::size_t>(busy[s]));
    }
    if (in_flight == 0) return;
    WorkerSlots::Event e = slots.wait(200);
    if (e.kind == Kind::None) {
      if (events.idle) events.idle();
      continue;
    }
    const auto index = static_cast<std::size_t>(busy[static_cast<std::size_t>(e.slot)]);
    busy[static_cast<std::size_t>(e.slot)] = -1;
    --in_flight;
    if (e.kind == Kind::Done) {
      e.row.attempts = deaths.count(index) ? 2 : 1;
      events.done(std::move(e.row), e.slot);
      continue;
    }
    if (++deaths[index] == 1) {
      queue.push_front(index);  // once more, on the next free worker
      continue;
    }
    RunRow failed;
    failed.run = static_cast<std::int64_t>(index);
    failed.reason = "its worker died twice (last: " + e.reason + ")";
    failed.attempts = 2;
    events.done(std::move(failed), e.slot);
  }
}

}  // namespace stride::sweep
