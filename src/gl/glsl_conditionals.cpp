// glsl_conditionals.cpp — a small preprocessor for #if chains over known integer macros.
#include "marchbox/gl/glsl_conditionals.h"

#include <cctype>
#include <sstream>
#include <vector>

namespace mb {

namespace {

// Recursive descent over the C precedence levels the shaders use.
class Expr {
public:
    Expr(const std::string& text, const Defines& defines) : s_(text), defines_(defines) {}

    bool eval(long* out) {
        *out = orExpr();
        skipSpace();
        return ok_ && pos_ == s_.size();
    }

private:
    void skipSpace() {
        while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    }
    bool take(const char* op) {
        skipSpace();
        size_t n = std::char_traits<char>::length(op);
        if (s_.compare(pos_, n, op) != 0) return false;
        // "<" must not swallow "<=", nor "!" the start of "!=".
        if (n == 1 && pos_ + 1 < s_.size() && s_[pos_ + 1] == '=' &&
            (*op == '<' || *op == '>' || *op == '!'))
            return false;
        pos_ += n;
        return true;
    }
    long orExpr() {
        long v = andExpr();
        while (take("||")) v = andExpr() || v;
        return v;
    }
    long andExpr() {
        long v = compare();
        while (take("&&")) v = compare() && v;
        return v;
    }
    long compare() {
        long v = sum();
        for (;;) {
            if (take("==")) v = v == sum();
            else if (take("!=")) v = v != sum();
            else if (take("<=")) v = v <= sum();
            else if (take(">=")) v = v >= sum();
            else if (take("<")) v = v < sum();
            else if (take(">")) v = v > sum();
            else return v;
        }
    }
    long sum() {
        long v = product();
        for (;;) {
            if (take("+")) v += product();
            else if (take("-")) v -= product();
            else return v;
        }
    }
    long product() {
        long v = unary();
        for (;;) {
            if (take("*")) v *= unary();
            else if (take("/")) {
                long d = unary();
                v = d ? v / d : (ok_ = false, 0);
            } else return v;
        }
    }
    long unary() {
        if (take("!")) return !unary();
        if (take("-")) return -unary();
        if (take("(")) {
            long v = orExpr();
            if (!take(")")) ok_ = false;
            return v;
        }
        return atom();
    }
    long atom() {
        skipSpace();
        size_t start = pos_;
        while (pos_ < s_.size() &&
               (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
            ++pos_;
        std::string tok = s_.substr(start, pos_ - start);
        if (tok.empty()) return ok_ = false, 0;
        if (std::isdigit(static_cast<unsigned char>(tok[0]))) return std::stol(tok);
        auto it = defines_.find(tok);
        return it == defines_.end() ? 0 : it->second;
    }

    const std::string& s_;
    const Defines& defines_;
    size_t pos_ = 0;
    bool ok_ = true;
};

struct Branch {
    bool parentActive;  // the enclosing block is emitted
    bool taken;         // some branch of this chain was already true
    bool active;        // the current branch is emitted
    int line;           // of its #if
};

std::string directive(const std::string& line, std::string* rest) {
    size_t p = line.find_first_not_of(" \t");
    if (p == std::string::npos || line[p] != '#') return "";
    size_t end = line.find_first_of(" \t", p);
    std::string word =
        line.substr(p + 1, end == std::string::npos ? std::string::npos : end - p - 1);
    *rest = end == std::string::npos ? "" : line.substr(end);
    size_t comment = rest->find("//");
    if (comment != std::string::npos) rest->erase(comment);
    return word;
}

}  // namespace

bool resolveConditionals(const std::string& source, const Defines& defines, std::string* out,
                         std::string* error, LineMap* lines) {
    std::istringstream in(source);
    std::vector<Branch> stack;
    std::string line, rest, result;
    LineMap kept;
    int lineNo = 0;
    auto where = [&](int n) {
        if (!lines) return "line " + std::to_string(n);
        const LineOrigin& o = lines->at(size_t(n - 1));
        return o.file + ':' + std::to_string(o.line);
    };
    auto active = [&] { return stack.empty() || stack.back().active; };
    auto condition = [&](bool* value) {
        long v = 0;
        if (!Expr(rest, defines).eval(&v)) {
            *error = where(lineNo) + ": cannot evaluate '#if" + rest + "'";
            return false;
        }
        *value = v != 0;
        return true;
    };
    while (std::getline(in, line)) {
        ++lineNo;
        std::string word = directive(line, &rest);
        bool value = false;
        if (word == "if") {
            if (!condition(&value)) return false;
            stack.push_back({active(), value, active() && value, lineNo});
        } else if (word == "elif" || word == "else" || word == "endif") {
            if (stack.empty()) {
                *error = where(lineNo) + ": #" + word + " without #if";
                return false;
            }
            Branch& b = stack.back();
            if (word == "endif") stack.pop_back();
            else if (word == "else") b.active = b.parentActive && !b.taken, b.taken = true;
            else {
                if (!condition(&value)) return false;
                b.active = b.parentActive && !b.taken && value;
                b.taken = b.taken || value;
            }
        } else if (active()) {
            result += line + '\n';
            if (lines) kept.push_back(lines->at(size_t(lineNo - 1)));
        }
    }
    if (!stack.empty()) {
        *error = where(stack.back().line) + ": #if without #endif";
        return false;
    }
    *out = std::move(result);
    if (lines) *lines = std::move(kept);
    return true;
}

}  // namespace mb
