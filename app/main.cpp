// prism: the command line. Parses arguments and hands them to a command.
#include "bench_command.h"
#include "completion.h"
#include "config_file.h"
#include "convert_command.h"
#include "info_command.h"
#include "render_command.h"
#include "sweep_command.h"
#include "view_command.h"

#include "process_launch.h"

#include "core/io/pending_file.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

namespace {

// Under AddressSanitizer, looks for leaks as main ends rather than at exit.
// At exit, static destructors of libraries OpenImageIO pulls in (log4cplus)
// stop their worker threads, and LeakSanitizer's own check, stopping the
// world while those threads were exiting, crashed in its tracer on a loaded
// CI machine (google/sanitizers#1353). Here every thread is idle; the check at
// exit is then skipped, as LeakSanitizer checks once.
void checkLeaksWhileThreadsAreIdle() {
#if defined(__SANITIZE_ADDRESS__)
  __lsan_do_leak_check();
#endif
}

} // namespace

#if defined(__SANITIZE_ADDRESS__)
// Open MPI keeps what MPI_Init allocated after MPI_Finalize (its components,
// hwloc's topology, libevent's bases): not Prism's leaks. Allocations made
// inside those libraries are not reported; Prism's own, in the module
// libprism_mpi.so or anywhere else, still are.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libmpi.so\n"
         "leak:/openmpi/\n" // its components
         "leak:libopen-pal.so\n"
         "leak:libopen-rte.so\n"
         "leak:libhwloc.so\n"
         "leak:libevent\n"
         "leak:libpmix\n";
}
// ... and says nothing of them: a quiet run's stderr stays empty.
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
#endif

namespace {

int runPrism(int argc, char** argv) {
  using namespace prism;
  CLI::App app{"Prism: a recursive ray tracer with adaptive antialiasing and automatic exposure"};
  app.set_version_flag("--version", "prism " PRISM_VERSION);
  app.require_subcommand(1);
  addConfigOption(app);

  RenderCommandOptions render;
  CLI::App* renderCmd = addRenderCommand(app, render);

  BenchCommandOptions bench;
  CLI::App* benchCmd = addBenchCommand(app, bench);

  ViewCommandOptions view;
  CLI::App* viewCmd = addViewCommand(app, view);

  ConvertCommandOptions convert;
  CLI::App* convertCmd = addConvertCommand(app, convert);

  SweepCommandOptions sweep;
  CLI::App* sweepCmd = addSweepCommand(app, sweep);

  InfoCommandOptions info;
  CLI::App* infoCmd = addInfoCommand(app, info);

  // Hidden: the build writes the installed bash completion with it.
  addBashCompletionFlag(app, "prism", /*fileAtTop=*/true); // prism SCENE

  const std::vector<const char*> args = withDefaultCommand(app, argc, argv); // prism SCENE
  if (const std::vector<std::string> problems = configFileProblems(app, args); !problems.empty()) {
    for (const std::string& problem : problems)
      std::cerr << problem << "\n";
    return kExitUsage;
  }
  try {
    app.parse(int(args.size()), args.data());
  } catch (const CLI::ParseError& error) {
    if (const std::optional<std::string> located = locateConfigError(args, error.what())) {
      std::cerr << *located << "\n";
      return kExitUsage;
    }
    const int code = app.exit(error);
    return code == 0 ? kExitOk : kExitUsage;
  }
  // Ctrl-C or a kill while a file is being written must not leave its
  // temporary behind.
  removePendingFilesOnSignals();
  // Commands report their own errors; what reaches here (memory exhausted on
  // any thread, say) still ends with a message and the failure status, not
  // with std::terminate and a core dump.
  // Under an MPI launcher render and sweep run as one job over the processes
  // (docs/distributed.md); the other commands are for one process.
  std::unique_ptr<ProcessGroup> group;
  if (const std::optional<std::string> problem = srunWithoutMpiProblem();
      problem && (renderCmd->parsed() || sweepCmd->parsed())) {
    std::cerr << "prism: error: " << *problem << "\n";
    return kExitUsage;
  }
  if (startedByMpiLauncher()) {
    if (!renderCmd->parsed() && !sweepCmd->parsed()) {
      std::cerr << "prism: error: only `prism render` and `prism sweep` run under an MPI "
                   "launcher\n";
      return kExitUsage;
    }
    std::string problem;
    group = joinProcessGroup(problem);
    if (!group) {
      std::cerr << "prism: error: " << problem << "\n";
      return kExitFailure;
    }
  }
  // A failure that reaches here on one process of a job ends them all: the
  // others may be waiting for it.
  auto fail = [&](const std::string& message) {
    std::cerr << "prism: error: " << message << "\n";
    if (group && group->size() > 1) group->abort(kExitFailure);
    return kExitFailure;
  };
  try {
    // Under MPI the leak check must come before MPI_Finalize (the group's
    // end): Open MPI then unloads its components, and what they keep
    // allocated would be reported from unknown modules.
    if (renderCmd->parsed()) {
      const int status = runRenderCommand(render, group.get());
      checkLeaksWhileThreadsAreIdle();
      return status;
    }
    if (viewCmd->parsed()) return runViewCommand(view);
    if (benchCmd->parsed()) return runBenchCommand(bench);
    if (convertCmd->parsed()) return runConvertCommand(convert);
    if (infoCmd->parsed()) return runInfoCommand(info);
    if (sweepCmd->parsed()) {
      const int status = runSweepCommand(sweep, group.get());
      checkLeaksWhileThreadsAreIdle();
      return status;
    }
  } catch (const std::bad_alloc&) {
    return fail("out of memory");
  } catch (const std::exception& error) {
    return fail(error.what());
  }
  return kExitUsage;
}

} // namespace

int main(int argc, char** argv) {
  const int status = runPrism(argc, argv);
  checkLeaksWhileThreadsAreIdle();
  return status;
}
