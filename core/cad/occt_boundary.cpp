#include "core/cad/occt_boundary.hpp"

#include <cmath>

namespace pl {

namespace {

// Asks OCCT's operation to stop once the deadline has passed; shows nothing.
class DeadlineIndicator final : public Message_ProgressIndicator {
 public:
  explicit DeadlineIndicator(const CadDeadline& d) : deadline_(d) {}
  Standard_Boolean UserBreak() override { return deadline_.passed(); }
  void Show(const Message_ProgressScope&, const Standard_Boolean) override {}

 private:
  CadDeadline deadline_;  // a copy: the indicator may outlive the caller's object
};

}  // namespace

CadDeadline::CadDeadline(double seconds) : seconds_(seconds) {
  if (seconds > 0 && std::isfinite(seconds))
    end_ = std::chrono::steady_clock::now() +
           std::chrono::duration_cast<std::chrono::steady_clock::duration>(
               std::chrono::duration<double>(seconds));
}

bool CadDeadline::passed() const {
  return seconds_ > 0 && std::isfinite(seconds_) && std::chrono::steady_clock::now() >= end_;
}

Handle(Message_ProgressIndicator) CadDeadline::indicator() const {
  return new DeadlineIndicator(*this);
}

std::string occt_failure_text(const Standard_Failure& f) {
  std::string r = f.DynamicType()->Name();
  const char* m = f.GetMessageString();
  if (m && *m) r += std::string(": ") + m;
  return r;
}

}  // namespace pl
