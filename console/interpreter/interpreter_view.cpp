// The console's `view [[host:]port] [token-file] | view stop`: the live view in a browser for
// whatever the console acts on (console/view/), beside the REPL or a script. Its pages' commands
// run between the console's own (idle(), run_slice()).
#include <ostream>

#include "console/interpreter/interpreter.hpp"
#include "console/view/view_bridge.hpp"
#include "console/view/view_options.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

void Interpreter::view(const std::vector<std::string>& a) {
  if (!a.empty() && a[0] == "stop") {
    if (!view_) throw Error("view stop: no view is open");
    view_.reset();
    out_ << "view stopped\n";
    return;
  }
  if (view_) throw Error("view: already open at " + view_->url() + " (view stop first)");
  view::WebServerOptions options =
      view::view_server_options(a.empty() ? "8080" : a[0], a.size() > 1 ? a[1] : "", "view");
  view_ = std::make_unique<view::ViewBridge>(*this, out_, std::move(options),
                                             remote_ ? "remote" : "sim");
  out_ << "view: " << view_->url() << " (open it in a browser; view stop closes it)\n";
}

void Interpreter::poll_view() {
  if (view_) view_->poll();
}

}  // namespace stride::console
