// Numbers as the previewer shows them.
#pragma once

#include <string>

namespace prism {

// 1054751 as "1,054,751": counts of primitives and rays read at a glance.
inline std::string withSeparators(long long value) {
  std::string digits = std::to_string(value);
  const std::size_t first = value < 0 ? 1 : 0; // after the sign
  for (int i = int(digits.size()) - 3; i > int(first); i -= 3)
    digits.insert(std::size_t(i), ",");
  return digits;
}

} // namespace prism
