// scoped_env.h — sets (or clears) an environment variable for one scope and puts the old value
// back, so no test changes what the tests after it see, whatever order gtest runs them in.
#pragma once

#include <cstdlib>
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

}  // namespace mb::test
