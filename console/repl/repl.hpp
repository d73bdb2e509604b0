#pragma once
// The interactive console: GNU readline with history (~/.stride_history) and tab completion.
// Without a terminal on stdin, lines are read plainly (for pipes); errors never end the session.
// `run` without seconds runs in the background while the prompt stays usable: the loop reads
// the keyboard between simulation steps, so every command applies between frames, on the one
// thread that owns the simulation. Ctrl-C pauses a run.
#include "console/interpreter/interpreter.hpp"

namespace stride::console {

// Runs until `quit` or end of input; returns 0.
int run_repl(Interpreter& interpreter);

}  // namespace stride::console
