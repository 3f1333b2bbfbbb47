#include "app/editor/logic/compare_figures.hpp"

#include <algorithm>
#include <chrono>

#include "core/base/data_error.hpp"

namespace pl {

CompareFigures::~CompareFigures() {
  if (job_) job_->cancel = true;
  if (worker_.valid()) worker_.wait();
  for (auto& f : cancelled_) f.wait();
}

void CompareFigures::cancel() {
  if (!job_) return;
  job_->cancel = true;
  cancelled_.push_back(std::move(worker_));
  job_.reset();
}

bool CompareFigures::request(const Scene& scene, const FiguresKey& key) {
  if (job_ ? job_->key == key : (result_key_ == key && (result_ || !error_.empty()))) return false;
  cancel();
  std::erase_if(cancelled_, [](const std::future<void>& f) {
    return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  });
  auto job = std::make_shared<Job>();
  job->key = key;
  job_ = job;
  ComparisonOptions o;
  o.faces = key.faces;
  o.schemes = key.schemes;
  o.base = key.base;
  o.density = key.density;
  o.timing_ms = timing_ms;
  o.cancelled = [job] { return job->cancel.load(); };
  worker_ = std::async(std::launch::async, [job, o, scene]() {
    try {
      job->result = compare_schemes(scene, o, "scene");
    } catch (const ComparisonCancelled&) {
    } catch (const DataError& e) {
      job->error = e.what();
    } catch (const std::exception& e) {
      job->error = e.what();
    }
  });
  return true;
}

bool CompareFigures::poll() {
  if (!job_ || worker_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  worker_.get();
  result_key_ = job_->key;
  result_ = std::move(job_->result);
  error_ = std::move(job_->error);
  job_.reset();
  return true;
}

std::vector<int> figures_faces(const Network& network, const std::vector<int>& selected) {
  std::vector<int> out;
  for (int f : selected)
    if (f >= 0 && f < int(network.faces.size()) &&
        std::find(out.begin(), out.end(), f) == out.end())
      out.push_back(f);
  if (!out.empty() || network.faces.empty()) return out;
  int best = 0;
  for (int f = 1; f < int(network.faces.size()); ++f)
    if (network.faces[f].loop.size() > network.faces[best].loop.size()) best = f;
  return {best};
}

}  // namespace pl
