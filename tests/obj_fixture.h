// A scratch directory for OBJ and MTL files, and the messages of loading one
// with the directory shown as DIR: the fixture of the OBJ tests.
#pragma once

#include "core/io/diagnostic.h"
#include "core/io/obj_reader.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace prism::test {

class ObjFiles : public ::testing::Test {
protected:
  std::filesystem::path write(const std::string& name, const std::string& text) {
    writeFile(dir_ / name, text);
    return dir_ / name;
  }

  // The messages of loading `obj` (and `mtl` as t.mtl), the scratch
  // directory shown as DIR; "no error" when it loads.
  std::string errorsOf(const std::string& obj, const std::string& mtl = "") {
    if (!mtl.empty()) write("t.mtl", mtl);
    try {
      loadObj(write("t.obj", obj));
    } catch (const SceneError& e) {
      std::string text = e.what();
      const std::string dir = dir_.string() + "/";
      for (std::size_t at; (at = text.find(dir)) != std::string::npos;)
        text.replace(at, dir.size(), "DIR/");
      return text;
    }
    return "no error";
  }

  ScratchDir scratch_;
  const std::filesystem::path dir_ = scratch_.path();
};

} // namespace prism::test
