#include "app/editor/logic/cad_export_job.hpp"

#include "core/base/data_error.hpp"

namespace pl {

CadExportJob::~CadExportJob() {
  if (future_.valid()) future_.wait();
}

bool CadExportJob::start(Scene scene, std::filesystem::path target, CadExportOptions options,
                         std::function<void()> finished) {
  if (running()) return false;
  target_ = target;
  started_ = Clock::now();
  future_ = std::async(
      std::launch::async, [scene = std::move(scene), target = std::move(target),
                           options = std::move(options), finished = std::move(finished)] {
        Result r;
        r.target = target;
        try {
          r.text = cad_report_text(export_cad(scene, target, options));
          r.ok = true;
        } catch (const DataError& e) {
          r.text = e.what();
        } catch (const std::exception& e) {  // out of memory, an OpenCASCADE failure
          r.text = target.string() + ": " + e.what();
        }
        if (finished) finished();
        return r;
      });
  return true;
}

double CadExportJob::seconds(Clock::time_point now) const {
  return running() ? std::chrono::duration<double>(now - started_).count() : 0.0;
}

std::optional<CadExportJob::Result> CadExportJob::poll() {
  if (!future_.valid() || future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return std::nullopt;
  return future_.get();
}

}  // namespace pl
