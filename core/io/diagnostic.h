// How every scene reader (.sc, NFF, OBJ/MTL) reports a problem: a Diagnostic
// with file, line and column, printed "FILE:LINE:COLUMN: error: MESSAGE"; a
// reader collects all it can and throws them together as a SceneError.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace prism {

struct Diagnostic {
  std::string file; // as the user named it (the include path for included files)
  int line = 0;     // 1-based
  int column = 0;   // 1-based, in bytes
  std::string message;

  // "FILE:LINE:COLUMN: SEVERITY: MESSAGE", the file name and message made printable.
  std::string format(const char* severity = "error") const;
};

class SceneError : public std::runtime_error {
public:
  explicit SceneError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

private:
  std::vector<Diagnostic> diagnostics_;
};

} // namespace prism
