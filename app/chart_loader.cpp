// writeChartPng for the `prism` executable: the drawing (OpenImageIO) is in
// the module libprism_oiio.so, loaded on the first chart (core/io/oiio_module.h).
#include "chart.h"

#include "core/io/oiio_module.h"

#include <stdexcept>

namespace prism {

std::string writeChartPng(const Chart& chart, const std::string& path, int width, int height) {
  using WriteChartFn =
      int (*)(const Chart*, const char*, int, int, std::string*, std::string*, int*);
  auto draw = reinterpret_cast<WriteChartFn>(oiioModuleSymbol("prism_oiio_write_chart"));
  std::string warnings, error;
  int invalidArgument = 0;
  if (draw(&chart, path.c_str(), width, height, &warnings, &error, &invalidArgument))
    return warnings;
  if (invalidArgument) throw std::invalid_argument(error);
  throw std::runtime_error(error);
}

} // namespace prism
