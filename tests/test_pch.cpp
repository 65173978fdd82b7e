// The source of prism_test_pch (tests/CMakeLists.txt), the target that
// compiles the test files' precompiled header: it needs one file to compile,
// and compiles nothing of its own.
