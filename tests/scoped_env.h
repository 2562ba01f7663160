// scoped_env.h — sets (or clears) an environment variable, or the working folder, for one scope
// and puts the old one back, so no test changes what the tests after it see, whatever order
// gtest runs them in.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace mb::test {

class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {  // value null: unset it
        if (const char* old = std::getenv(name)) old_ = old;
        value ? setenv(name, value, 1) : unsetenv(name);
    }
    ~ScopedEnv() { old_ ? setenv(name_.c_str(), old_->c_str(), 1) : unsetenv(name_.c_str()); }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    std::string name_;
    std::optional<std::string> old_;
};

// Messages name files from the working folder, which differs between CTest (the build folder)
// and a binary started by hand: a test that reads them fixes it first.
class ScopedCwd {
public:
    explicit ScopedCwd(const std::filesystem::path& dir) : old_(std::filesystem::current_path()) {
        std::filesystem::current_path(dir);
    }
    ~ScopedCwd() { std::filesystem::current_path(old_); }
    ScopedCwd(const ScopedCwd&) = delete;
    ScopedCwd& operator=(const ScopedCwd&) = delete;

private:
    std::filesystem::path old_;
};

}  // namespace mb::test
