#pragma once
// The interactive console: GNU readline with history (~/.stride_history) and tab completion.
// Without a terminal on stdin, lines are read plainly (for pipes); errors never end the session.
#include "console/interpreter/interpreter.hpp"

namespace stride::console {

// Runs until `quit` or end of input; returns 0.
int run_repl(Interpreter& interpreter);

}  // namespace stride::console
