// The .deb as a user gets it (packaging/CMakeLists.txt, docs/installing.md):
// built from this build tree with cpack, unpacked with `dpkg -x` into a
// scratch root, and used from there: its dependencies, every library of the
// program and its modules resolved, a render with the installed program (and
// its module found beside it), the manual page and the bash completion, and a
// program of one's own built against the unpacked core library with
// find_package(Prism) and with pkg-config. One test, as the steps build on
// each other and the package is built once.
#include "tests/test_files.h"

#include <gtest/gtest.h>

#include <tiffio.h>

#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace prism::test;
namespace fs = std::filesystem;

// A run's output for a failure message.
std::string shown(const RunResult& r) {
  return "exit " + std::to_string(r.exitCode) + "\nstdout:\n" + r.out + "\nstderr:\n" + r.err;
}

// `text` as one shell word, whatever quotes it holds.
std::string shellWord(const std::string& text) {
  std::string word = "'";
  for (const char c : text)
    word += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return word + "'";
}

// The width and height of a TIFF file, or {0, 0} if libtiff cannot read it.
std::pair<int, int> tiffSize(const fs::path& file) {
  TIFF* tiff = TIFFOpen(file.c_str(), "r");
  if (!tiff) return {0, 0};
  uint32_t width = 0, height = 0;
  TIFFGetField(tiff, TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(tiff, TIFFTAG_IMAGELENGTH, &height);
  TIFFClose(tiff);
  return {int(width), int(height)};
}

// The commands `prism --help` lists under "Subcommands:" (first names).
std::vector<std::string> commandsIn(const std::string& help) {
  std::vector<std::string> commands;
  const std::size_t start = help.find("\nSubcommands:\n");
  if (start == std::string::npos) return commands;
  std::istringstream lines(help.substr(start + 13));
  for (std::string line; std::getline(lines, line);)
    if (line.size() > 2 && line.rfind("  ", 0) == 0 &&
        std::islower(static_cast<unsigned char>(line[2])))
      commands.push_back(line.substr(2, line.find_first_of(", ", 2) - 2));
  return commands;
}

// `text` with each line starting with `key` replaced by `line`, and how many.
std::pair<std::string, int> replaceLines(const std::string& text, const std::string& key,
                                         const std::string& line) {
  std::istringstream in(text);
  std::string out;
  int replaced = 0;
  for (std::string l; std::getline(in, l);) {
    if (l.rfind(key, 0) == 0) {
      l = line;
      ++replaced;
    }
    out += l + "\n";
  }
  return {out, replaced};
}

// The file the package holds at `relative` below ROOT/usr, found wherever
// LIBDIR puts it (lib or lib/x86_64-linux-gnu).
fs::path findBelow(const fs::path& root, const std::string& name) {
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.path().filename() == name) return entry.path();
  return {};
}

TEST(Package, DebInstallsAWorkingPrism) {
  ScratchDir scratch;
  const fs::path dir = scratch.path();

  // The package, from this build tree's install rules; its working files in
  // the scratch folder too (not the build folder, which other tests share).
  const RunResult cpack =
      run(dir, "cpack -G DEB --config " + quoted(fs::path(PRISM_BUILD_DIR) / "CPackConfig.cmake") +
                   " -B " + quoted(dir / "cpack"));
  ASSERT_EQ(cpack.exitCode, 0) << shown(cpack);
  fs::path deb;
  for (const auto& entry : fs::directory_iterator(dir / "cpack"))
    if (entry.path().extension() == ".deb") deb = entry.path();
  ASSERT_FALSE(deb.empty()) << "cpack wrote no .deb:\n" << shown(cpack);
  std::cout << "package: " << deb.filename().string() << ", " << fs::file_size(deb) << " bytes\n";

  // Its control data: the name, the section and the libraries the program
  // and the modules need.
  const RunResult info = run(dir, "dpkg-deb -I " + quoted(deb));
  ASSERT_EQ(info.exitCode, 0) << shown(info);
  EXPECT_NE(info.out.find("Package: prism"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("Section: graphics"), std::string::npos) << info.out;
  const std::size_t depends = info.out.find("Depends: ");
  ASSERT_NE(depends, std::string::npos) << info.out;
  const std::string dependsLine = info.out.substr(depends, info.out.find('\n', depends) - depends);
  std::vector<std::string> needed = {"libopenimageio", "libtiff", "libpng", "libstdc++"};
#ifdef PRISM_HAVE_PREVIEWER
  needed.insert(needed.end(), {"libglfw3", "libopengl0", "libgl1"});
#endif
#ifdef PRISM_HAVE_MPI_MODULE
  needed.push_back("libopenmpi");
#endif
  for (const std::string& package : needed)
    EXPECT_NE(dependsLine.find(package), std::string::npos) << package << " in " << dependsLine;

  // Unpacked into a fresh root, as a relocated install.
  const fs::path root = dir / "root";
  const RunResult unpack = run(dir, "dpkg -x " + quoted(deb) + " " + quoted(root));
  ASSERT_EQ(unpack.exitCode, 0) << shown(unpack);
  const fs::path usr = root / "usr";
  const fs::path prism = usr / "bin" / "prism";
  ASSERT_TRUE(fs::is_regular_file(prism));
  const fs::path oiioModule = findBelow(usr, "libprism_oiio.so");
  ASSERT_FALSE(oiioModule.empty()) << "no libprism_oiio.so in the package";
  EXPECT_EQ(oiioModule.parent_path().filename(), "prism") << oiioModule;
  std::vector<fs::path> binaries = {prism, oiioModule};
#ifdef PRISM_HAVE_MPI_MODULE
  const fs::path mpiModule = findBelow(usr, "libprism_mpi.so");
  ASSERT_FALSE(mpiModule.empty()) << "no libprism_mpi.so in the package";
  EXPECT_EQ(mpiModule.parent_path(), oiioModule.parent_path());
  binaries.push_back(mpiModule);
#endif
  EXPECT_TRUE(fs::is_regular_file(findBelow(usr, "libprism_core.a")));
  EXPECT_TRUE(fs::is_regular_file(usr / "include/prism/core/render/renderer.h"));

  // Every library of the program and of the modules resolves.
  for (const fs::path& binary : binaries) {
    const RunResult ldd = run(dir, "ldd " + quoted(binary));
    EXPECT_EQ(ldd.exitCode, 0) << binary << "\n" << shown(ldd);
    EXPECT_EQ(ldd.out.find("not found"), std::string::npos) << binary << "\n" << ldd.out;
  }

  // The installed program: its version, and a shipped scene rendered to an
  // 8-bit TIFF and to EXR, which only the module writes (found in the
  // unpacked root: the build tree is nowhere near the installed program).
  const RunResult version = run(dir, quoted(prism) + " --version");
  EXPECT_EQ(version.exitCode, 0) << shown(version);
  EXPECT_EQ(version.out, "prism " PRISM_VERSION "\n");
  const fs::path scenes = usr / "share/prism/scenes";
  ASSERT_TRUE(fs::is_regular_file(scenes / "glass.sc"));
  for (const std::string picture : {"glass.tif", "glass.exr"}) {
    const RunResult render = run(dir, quoted(prism) + " render " + quoted(scenes / "glass.sc") +
                                          " --size 64 48 -q -o " + quoted(dir / picture));
    EXPECT_EQ(render.exitCode, 0) << picture << "\n" << shown(render);
    EXPECT_TRUE(fs::is_regular_file(dir / picture)) << picture;
  }
  EXPECT_EQ(tiffSize(dir / "glass.tif"), std::make_pair(64, 48));
  // The included parts and images came along: each shipped scene is read.
  for (const auto& entry : fs::directory_iterator(scenes)) {
    if (entry.path().extension() != ".sc") continue;
    const RunResult check = run(dir, quoted(prism) + " check " + quoted(entry.path()));
    EXPECT_EQ(check.exitCode, 0) << entry.path() << "\n" << shown(check);
  }

  // The manual page names every command the program lists.
  const RunResult help = run(dir, quoted(prism) + " --help");
  const std::vector<std::string> commands = commandsIn(help.out);
  ASSERT_GE(commands.size(), 6u) << help.out;
  const fs::path manPage = usr / "share/man/man1/prism.1.gz";
  ASSERT_TRUE(fs::is_regular_file(manPage));
  const RunResult man = run(dir, "gzip -dc " + quoted(manPage));
  ASSERT_EQ(man.exitCode, 0) << shown(man);
  EXPECT_NE(man.out.find(".TH PRISM \"1\""), std::string::npos) << man.out.substr(0, 500);
  for (const std::string& command : commands)
    EXPECT_NE(man.out.find(".SS \"prism " + command + "\""), std::string::npos) << command;
  EXPECT_NE(man.out.find("\\-\\-thresh"), std::string::npos); // a command's own option

  // The bash completion, its function called as bash would (in an empty
  // folder, so that no file name is offered besides).
  const fs::path completion = usr / "share/bash-completion/completions/prism";
  ASSERT_TRUE(fs::is_regular_file(completion));
  fs::create_directories(dir / "empty");
  auto complete = [&](const std::string& words, int cword) {
    return run(dir / "empty",
               "bash -c " +
                   shellWord("source " + shellWord(completion.string()) + " && COMP_WORDS=(" +
                             words + ") && COMP_CWORD=" + std::to_string(cword) +
                             " && _prism && printf '%s\\n' \"${COMPREPLY[@]}\""));
  };
  const RunResult ren = complete("prism ren", 1);
  EXPECT_EQ(ren.out, "render\n") << shown(ren);
  const RunResult th = complete("prism render --th", 2);
  EXPECT_NE(th.out.find("--thresh\n"), std::string::npos) << shown(th);
  EXPECT_NE(th.out.find("--threads\n"), std::string::npos) << shown(th);
  const RunResult top = complete("prism ''", 1);
  for (const std::string& command : commands)
    EXPECT_NE(top.out.find(command + "\n"), std::string::npos) << command << "\n" << shown(top);
  const RunResult accel = complete("prism render scene.sc --accel ''", 4);
  EXPECT_EQ(accel.out, "bvh\ngroups\nnone\n") << shown(accel);
  const RunResult bound =
      run(dir, "bash -c " +
                   shellWord("source " + shellWord(completion.string()) + " && complete -p prism"));
  EXPECT_EQ(bound.out, "complete -F _prism prism\n") << shown(bound);

  // Under the sanitizers the installed library is instrumented, and a
  // program linking it must be too; otherwise nothing is added. The same
  // compiler as Prism's.
  const std::string flags = PRISM_SANITIZE_FLAGS;

  // A program of one's own against the unpacked core library, with
  // find_package(Prism) (examples/: `prism_example SCENE OUT.tif`), on a
  // shipped scene made small.
  const fs::path examples = fs::path(PRISM_SOURCE_DIR) / "examples";
  {
    const auto [small, resolutions] =
        replaceLines(slurp(scenes / "glass.sc"), "resolution ", "resolution 64 48");
    ASSERT_EQ(resolutions, 1);
    writeFile(scenes / "small-glass.sc", small);
    const std::string sanitize = flags.empty()
                                     ? ""
                                     : " -DCMAKE_CXX_FLAGS=" + shellWord(flags) +
                                           " -DCMAKE_EXE_LINKER_FLAGS=" + shellWord(flags);
    const RunResult configure =
        run(dir, "cmake -S " + quoted(examples) + " -B " + quoted(dir / "example") +
                     " -DCMAKE_PREFIX_PATH=" + quoted(usr) +
                     " -DCMAKE_CXX_COMPILER=" + shellWord(PRISM_CXX_COMPILER) + sanitize);
    ASSERT_EQ(configure.exitCode, 0) << shown(configure);
    const RunResult build = run(dir, "cmake --build " + quoted(dir / "example"));
    ASSERT_EQ(build.exitCode, 0) << shown(build);
    const RunResult example =
        run(dir, quoted(dir / "example/prism_example") + " " + quoted(scenes / "small-glass.sc") +
                     " " + quoted(dir / "example.tif"));
    EXPECT_EQ(example.exitCode, 0) << shown(example);
    EXPECT_EQ(tiffSize(dir / "example.tif"), std::make_pair(64, 48));
  }

  // pkg-config finds the core below the unpacked root (prism.pc names its
  // prefix relative to itself) with what a static link needs.
  const fs::path pcFile = findBelow(usr, "prism.pc");
  ASSERT_FALSE(pcFile.empty()) << "no prism.pc in the package";
  const RunResult pc = run(dir, "PKG_CONFIG_PATH=" + quoted(pcFile.parent_path()) +
                                    " pkg-config --cflags --libs prism");
  ASSERT_EQ(pc.exitCode, 0) << shown(pc);
  const RunResult pcStatic = run(dir, "PKG_CONFIG_PATH=" + quoted(pcFile.parent_path()) +
                                          " pkg-config --static --libs prism");
  ASSERT_EQ(pcStatic.exitCode, 0) << shown(pcStatic);
  for (const std::string flag : {"/include/prism", "-lprism_core"})
    EXPECT_NE(pc.out.find(flag), std::string::npos) << flag << " in " << pc.out;
  for (const std::string flag : {"-ltiff", "-lpng", "-ltinyobjloader_double"})
    EXPECT_NE(pcStatic.out.find(flag), std::string::npos) << flag << " in " << pcStatic.out;
  const std::size_t include = pc.out.find("-I");
  ASSERT_NE(include, std::string::npos) << pc.out;
  const std::string includeDir =
      pc.out.substr(include + 2, pc.out.find_first_of(" \n", include) - include - 2);
  EXPECT_TRUE(fs::is_regular_file(fs::path(includeDir) / "core/render/renderer.h")) << pc.out;
  // ... and they are enough: the example built with nothing but them.
  {
    const RunResult build =
        run(dir, shellWord(PRISM_CXX_COMPILER) + " -std=c++20 " + flags + " " +
                     quoted(examples / "render_scene.cpp") + " -o " + quoted(dir / "pc_example") +
                     " " + pc.out.substr(0, pc.out.find_last_not_of(" \n") + 1) + " " +
                     pcStatic.out.substr(0, pcStatic.out.find_last_not_of(" \n") + 1));
    ASSERT_EQ(build.exitCode, 0) << shown(build);
    const RunResult example =
        run(dir, quoted(dir / "pc_example") + " " + quoted(scenes / "small-glass.sc") + " " +
                     quoted(dir / "pc_example.tif"));
    EXPECT_EQ(example.exitCode, 0) << shown(example);
    EXPECT_EQ(tiffSize(dir / "pc_example.tif"), std::make_pair(64, 48));
  }

#ifdef PRISM_PYTHON
  // The Python package, unpacked: `import prism` from its dist-packages
  // folder runs the whole unittest suite (which reads the source tree's
  // scenes), finding the OpenImageIO module below the same prefix (its EXR
  // test needs it).
  const fs::path extension = findBelow(usr, "__init__.py").parent_path();
  ASSERT_EQ(extension.filename(), "prism") << "no Python package in the .deb";
  const std::string preload = PRISM_PYTHON_PRELOAD;
  // Run in the suite's folder, its output captured in the scratch folder:
  // nothing may be written into the source tree.
  const RunResult python =
      runCaptured("cd " + quoted(fs::path(PRISM_SOURCE_DIR) / "python/tests") + " && " +
                      "PYTHONPATH=" + quoted(extension.parent_path()) +
                      " PYTHONDONTWRITEBYTECODE=1 PRISM_SOURCE_DIR=" + quoted(PRISM_SOURCE_DIR) +
                      (preload.empty() ? std::string()
                                       : " LD_PRELOAD=" + quoted(fs::path(preload)) +
                                             " ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}"
                                             "detect_leaks=0\"") +
                      " " + quoted(PRISM_PYTHON) + " -m unittest test_prism",
                  dir);
  EXPECT_EQ(python.exitCode, 0) << shown(python);
  EXPECT_NE(python.err.find("Ran "), std::string::npos) << shown(python);
  EXPECT_EQ(python.err.find("Ran 0 tests"), std::string::npos) << shown(python);
  EXPECT_NE(python.err.find("\nOK"), std::string::npos) << shown(python);
  // ... and it is the unpacked one that was imported.
  const RunResult where =
      run(dir, "PYTHONPATH=" + quoted(extension.parent_path()) +
                   (preload.empty() ? std::string()
                                    : " LD_PRELOAD=" + quoted(fs::path(preload)) +
                                          " ASAN_OPTIONS=detect_leaks=0") +
                   " " + quoted(PRISM_PYTHON) + " -c 'import prism; print(prism.__file__)'");
  EXPECT_EQ(where.exitCode, 0) << shown(where);
  EXPECT_EQ(where.out.rfind(root.string(), 0), 0u) << where.out;
#endif
}

} // namespace
