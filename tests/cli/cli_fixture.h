// The fixture of the glint tool's end-to-end tests: a folder of the test's own, and glint run
// in it, waited for or not, with its output kept.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace glint {

namespace fs = std::filesystem;

struct Outcome {
    int exit_code;
    std::string out, err;
};

inline std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(GLINT_TEST_OUTPUT_DIR) /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }

    // `shell` runs first in the same shell, e.g. "ulimit -v 1000000 && ".
    Outcome run_glint(const std::string& args, const std::string& shell = "") const {
        return run(shell, "'" GLINT_BINARY "' " + args);
    }
    // `command` run by the shell in the test's folder, after `shell`.
    Outcome run(const std::string& shell, const std::string& command) const {
        const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
        const std::string line = shell + "cd '" + dir_.string() + "' && " + command + " > '" +
                                 out.string() + "' 2> '" + err.string() + "'";
        const int status = std::system(line.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
    }

    // Starts glint without waiting, its stdout and stderr going to files in the test's folder;
    // `environment` holds NAME=value entries to add to this process's.
    pid_t spawn_glint(std::vector<std::string> args,
                      std::vector<std::string> environment = {}) const {
        args.insert(args.begin(), GLINT_BINARY);
        return spawn(std::move(args), std::move(environment));
    }
    // Starts args[0], found on the PATH, likewise.
    pid_t spawn(std::vector<std::string> args, std::vector<std::string> environment = {}) const {
        std::vector<char*> argv;
        for (std::string& arg : args) argv.push_back(arg.data());
        argv.push_back(nullptr);
        std::vector<char*> envp;
        for (char** e = environ; *e; ++e) envp.push_back(*e);
        for (std::string& e : environment) envp.push_back(e.data());
        envp.push_back(nullptr);
        const std::string out = (dir_ / "stdout.txt").string(),
                          err = (dir_ / "stderr.txt").string();
        posix_spawn_file_actions_t files;
        posix_spawn_file_actions_init(&files);
        posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, out.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_addopen(&files, STDERR_FILENO, err.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        pid_t pid = -1;
        const int error = posix_spawnp(&pid, argv[0], &files, nullptr, argv.data(), envp.data());
        posix_spawn_file_actions_destroy(&files);
        return error == 0 ? pid : -1;
    }

    // The environment that holds a render after `tiles` tiles until it is stopped
    // (apps/glint/test_hold.h), and whether glint has said it holds.
    static std::vector<std::string> hold_after(int tiles) {
        return {"GLINT_TEST_HOLD_AFTER_TILES=" + std::to_string(tiles)};
    }
    bool holding() const {
        return slurp(dir_ / "stderr.txt").find("glint: holding after") != std::string::npos;
    }
    // Waits (a minute at most) for glint `pid`, started with hold_after, to hold, stops it with
    // SIGINT, and returns how it ended: its exit status (-1 when it never held or was killed)
    // and its standard error. A SIGINT that glint has not acted on within a minute is sent again
    // (under ThreadSanitizer, which defers signals, one was seen never to arrive), and after
    // three minutes glint is killed: a stop that fails fails the test, and never hangs it.
    Outcome stop_when_held(pid_t pid) const {
        for (int waited = 0; !holding() && waited < 60000; waited += 5) usleep(5000);
        const bool held = holding();
        kill(pid, held ? SIGINT : SIGKILL);
        int status = 0;
        bool killed = !held;
        for (int waited = 0; waitpid(pid, &status, WNOHANG) == 0; waited += 5) {
            if (waited == 60000) kill(pid, SIGINT);
            if (waited >= 180000) {
                kill(pid, SIGKILL);
                waitpid(pid, &status, 0);
                killed = true;
                break;
            }
            usleep(5000);
        }
        const int code = !killed && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        return {code, slurp(dir_ / "stdout.txt"), slurp(dir_ / "stderr.txt")};
    }

    fs::path write_scene(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name) << text;
        return dir_ / name;
    }

    static std::string scene(const std::string& name) {
        return std::string("'") + GLINT_SOURCE_DIR + "/scenes/" + name + "'";
    }

    fs::path dir_;
};

}  // namespace glint
