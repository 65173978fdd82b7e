// A render called from Python (docs/python.md): the C++ render runs on a
// worker thread while the calling thread, without the GIL, waits for it; each
// few milliseconds, and at every tile, it takes the GIL back to call the
// progress callback with what the worker queued and to run Python's signal
// handlers (Ctrl-C). A Python exception there (KeyboardInterrupt, or one the
// callback raised) stops the render, waits for the worker, and propagates.
#pragma once

#include "core/api/prism.h"

#include <pybind11/pybind11.h>

namespace prism::python {

// `progress` is None or a callable (pass, fraction). Throws what
// api::render throws, pybind11::error_already_set for a Python exception.
api::Image renderFromPython(const api::LoadedScene& scene, const api::RenderOptions& options,
                            const pybind11::object& progress);

} // namespace prism::python
