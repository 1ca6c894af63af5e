// Bad command lines: exit code 2 and a message that says what is wrong.
#include <filesystem>

#include <gtest/gtest.h>

#include "cli/run_glimmer.h"

namespace glimmer_cli {
namespace {
namespace fs = std::filesystem;

TEST(CliUsage, NoSubcommand) {
    auto r = runGlimmer({});
    ASSERT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("A subcommand is required"), std::string::npos) << r.err;
}

TEST(CliUsage, UnknownSubcommandIsNamed) {
    auto r = runGlimmer({"rendr", "scripts/bloom.glib"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("glimmer: error: unknown command 'rendr'; the commands are 'render', 'check', 'view', 'sheet', 'tradeoff', 'batch', 'batch-merge' and 'serve'"),
              std::string::npos)
        << r.err;
}

TEST(CliUsage, HelpExitsZero) {
    auto r = runGlimmer({"--help"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("render"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("check"), std::string::npos) << r.out;
}

TEST(CliUsage, MissingScriptArgument) {
    auto r = runGlimmer({"render"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("script is required"), std::string::npos) << r.err;
}

TEST(CliUsage, UnknownOption) {
    TempDir dir;
    auto r = runGlimmer({"render", "scripts/bloom.glib", "-o", dir.file("x.png"), "--frobnicate"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("The following argument was not expected: --frobnicate"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
}

class CliBadSize : public ::testing::TestWithParam<const char*> {};

TEST_P(CliBadSize, IsAUsageError) {
    TempDir dir;
    auto r = runGlimmer({"render", "scripts/bloom.glib", "-o", dir.file("x.png"), "--size", GetParam(), "--backend",
                         "osmesa"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err, std::string("glimmer: error: --size '") + GetParam() +
                         "' is not WIDTHxHEIGHT (1 to 16384 each)\n");
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
}

INSTANTIATE_TEST_SUITE_P(Sizes, CliBadSize,
                         ::testing::Values("0x5", "abc", "64", "64x", "x64", "64x64x2", "-64x64", "16385x1", "6 4x64"));

TEST(CliUsage, BadSizeOnCheckToo) {
    auto r = runGlimmer({"check", "scripts/bloom.glib", "--size", "0x5", "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("glimmer: error: --size '0x5' is not WIDTHxHEIGHT"), std::string::npos) << r.err;
}

TEST(CliUsage, UnknownBackend) {
    TempDir dir;
    auto r = runGlimmer({"render", "scripts/bloom.glib", "-o", dir.file("x.png"), "--backend", "nope"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--backend: nope not in {auto,osmesa,egl,egl-device,egl-surfaceless,egl-gles}"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
}

// Every subcommand that makes a context refuses an unknown backend as it
// reads it, with one message (sheet said "unknown backend" only after
// loading the script; tradeoff, "--backend or --repeat is not valid").
TEST(CliUsage, UnknownBackendIsTheSameUsageErrorForEverySubcommand) {
    TempDir dir;
    const std::vector<std::vector<std::string>> commands{
        {"check", "scripts/bloom.glib"},
        {"sheet", "scripts/bloom.glib", "--vary", "uAdd=0,1", "-o", dir.file("s.png")},
        {"batch", "scripts/bloom.glib", "-o", dir.file("b")},
        {"tradeoff", "--size", "32x32", "-o", dir.file("t")}};
    for (auto args : commands) {
        args.insert(args.end(), {"--backend", "nope"});
        auto r = runGlimmer(args);
        EXPECT_EQ(r.exitCode, 2) << args[0] << ": " << r.err;
        EXPECT_EQ(r.err, "--backend: nope not in {auto,osmesa,egl,egl-device,egl-surfaceless,egl-gles}\n"
                         "Run with --help for more information.\n") << args[0];
    }
    EXPECT_TRUE(fs::is_empty(dir.path()));
    auto r = runGlimmer({"tradeoff", "--size", "32x32", "--repeat", "0", "-o", dir.file("t")});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err, "--repeat: Value 0 not in range 1 to 100000\nRun with --help for more information.\n");
}

class CliBadPngLevel : public ::testing::TestWithParam<const char*> {};

TEST_P(CliBadPngLevel, IsAUsageError) {
    TempDir dir;
    auto r = runGlimmer({"render", "scripts/bloom.glib", "-o", dir.file("x.png"), "--png-level", GetParam(),
                         "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err, std::string("glimmer: error: --png-level ") + GetParam() + " is not between 0 and 9\n");
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
}

INSTANTIATE_TEST_SUITE_P(Levels, CliBadPngLevel, ::testing::Values("10", "-1", "99"));

class CliBadDump : public ::testing::TestWithParam<const char*> {};

TEST_P(CliBadDump, IsAUsageError) {
    TempDir dir;
    auto r = runGlimmer({"render", "scripts/bloom.glib", "-o", dir.file("x.png"), "--dump", GetParam(),
                         "--backend", "osmesa"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err, std::string("glimmer: error: --dump '") + GetParam() +
                         "' is not UNIT=FILE with a unit from 0 to 31\n");
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
}

INSTANTIATE_TEST_SUITE_P(Dumps, CliBadDump, ::testing::Values("99=x.png", "32=x.png", "6", "6=", "=x.png", "a=x.png"));

TEST(CliUsage, ScriptThatDoesNotExist) {
    TempDir dir;
    for (std::string cmd : {"render", "check"}) {
        std::vector<std::string> args{cmd, "tests/data/cli/does_not_exist.glib", "--backend", "osmesa"};
        if (cmd == "render") args.insert(args.end(), {"-o", dir.file("x.png")});
        auto r = runGlimmer(args);
        EXPECT_EQ(r.exitCode, 2) << cmd << "\n" << r.err;
        EXPECT_NE(r.err.find("tests/data/cli/does_not_exist.glib: error: cannot open the script"), std::string::npos)
            << r.err;
    }
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
}

}  // namespace
}  // namespace glimmer_cli
