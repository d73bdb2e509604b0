#pragma once
// Sends what a stream prints into a string stream while alive (a page's command's output, or
// what loading prints before the view's URL line), then restores the stream.
#include <ostream>
#include <sstream>

namespace stride::view {

class OutputCapture {
 public:
  OutputCapture(std::ostream& out, std::ostringstream& into)
      : out_(out), old_(out.rdbuf(into.rdbuf())) {}
  ~OutputCapture() { out_.rdbuf(old_); }
  OutputCapture(const OutputCapture&) = delete;
  OutputCapture& operator=(const OutputCapture&) = delete;

 private:
  std::ostream& out_;
  std::streambuf* old_;
};

}  // namespace stride::view
