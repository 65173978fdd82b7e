#include "render_call.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <stop_token>
#include <thread>
#include <vector>

namespace py = pybind11;

namespace prism::python {

namespace {

// How long the calling thread sleeps between looks at Python's signals when
// no tile finishes: Ctrl-C is felt within this, plus a tile.
constexpr std::chrono::milliseconds kSignalPoll{20};

// What the worker hands the calling thread, under `mutex`.
struct Mailbox {
  std::mutex mutex;
  std::condition_variable wake;
  std::vector<api::Progress> progress; // not yet delivered to Python
  bool done = false;
  std::optional<api::Image> image;
  std::exception_ptr error;
};

// The worker thread, stopped and joined (without the GIL, which the worker
// never needs) however the calling thread leaves.
class Worker {
public:
  Worker(const api::LoadedScene& scene, const api::RenderOptions& options, Mailbox& box)
      : thread_([&scene, options, &box, token = stop_.get_token()] {
          std::optional<api::Image> image;
          std::exception_ptr error;
          try {
            image = api::render(
                scene, options,
                [&box](const api::Progress& p) {
                  {
                    const std::lock_guard lock(box.mutex);
                    box.progress.push_back(p);
                  }
                  box.wake.notify_one();
                },
                token);
          } catch (...) {
            error = std::current_exception();
          }
          {
            const std::lock_guard lock(box.mutex);
            box.image = std::move(image);
            box.error = error;
            box.done = true;
          }
          box.wake.notify_one();
        }) {}

  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  ~Worker() {
    stop_.request_stop();
    const py::gil_scoped_release release;
    thread_.join();
  }

  void stop() { stop_.request_stop(); }

private:
  std::stop_source stop_; // before thread_: the thread takes its token
  std::thread thread_;
};

} // namespace

api::Image renderFromPython(const api::LoadedScene& scene, const api::RenderOptions& options,
                            const py::object& progress) {
  Mailbox box;
  std::vector<api::Progress> batch;
  bool done = false;
  {
    Worker worker(scene, options, box);
    while (!done) {
      {
        const py::gil_scoped_release release;
        std::unique_lock lock(box.mutex);
        box.wake.wait_for(lock, kSignalPoll, [&] { return box.done || !box.progress.empty(); });
        batch.swap(box.progress);
        box.progress.clear();
        done = box.done;
      }
      // With the GIL: a Python exception leaves through ~Worker, which stops
      // the render and waits for it.
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none())
        for (const api::Progress& p : batch)
          progress(p.pass, p.fraction);
    }
  }
  if (box.error) std::rethrow_exception(box.error);
  return std::move(*box.image);
}

} // namespace prism::python
