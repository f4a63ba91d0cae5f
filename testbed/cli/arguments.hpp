// Testbed — the command-line argument reader every command uses: options
// with a value (`--steps 10`), flags, numbers and names checked against a
// range or a table, and the one way a usage error is reported (exit code 2,
// "testbed COMMAND: what is wrong", then a hint).
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "enum_names.hpp"

namespace tb {

/// Bad command-line arguments; what() is the message shown before the usage hint.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Exit code of every command for bad arguments.
inline constexpr int kUsageExitCode = 2;

/// True when any argument is -h or --help: help wins over everything else.
inline bool wantsHelp(const std::vector<std::string>& args) {
    for (const std::string& a : args)
        if (a == "-h" || a == "--help") return true;
    return false;
}

/// Prints "testbed COMMAND: MESSAGE" and then `hint` (ending in a newline) to
/// `err`; returns kUsageExitCode.
int reportUsageError(std::ostream& err, std::string_view command, const UsageError& error, std::string_view hint);

/// `text` as a whole integer in [lo, hi] (hi = INT_MAX: no upper limit); UsageError naming `option` otherwise.
long parseInteger(std::string_view option, const std::string& text, long lo, long hi);
/// `text` as a whole finite number in [lo, hi]; UsageError naming `option` otherwise.
double parseNumber(std::string_view option, const std::string& text, double lo, double hi);
/// "on" or "off".
bool parseOnOff(std::string_view option, const std::string& text);
/// "WxH" with each side in [lo, hi] (hi = INT_MAX: no upper limit).
std::pair<int, int> parseSize(std::string_view option, const std::string& text, int lo, int hi);

/// The value of E named `text` (see enum_names.hpp); UsageError listing the names otherwise.
template <class E>
E parseChoice(std::string_view option, const std::string& text) {
    if (auto v = enumFromName<E>(text)) return *v;
    throw UsageError(std::string(option) + ": expected " + enumNameList<E>() + ", got '" + text + "'");
}

/// Walks a command's arguments in order:
///
///     ArgReader r(args);
///     while (r.next()) {
///         if (r.is("--steps")) steps = r.integer(0, 1000);
///         else if (r.is("--json")) json = true;
///         else if (r.isOption()) r.rejectUnknownOption();
///         else scene = r.current();
///     }
///
/// The typed readers consume the option's value (the next argument) and throw
/// UsageError naming the option when it is missing or bad.
class ArgReader {
public:
    explicit ArgReader(std::vector<std::string> args) : args_(std::move(args)) {}

    /// Moves to the next argument; false when there is none left.
    bool next() { return ++index_ < args_.size(); }
    const std::string& current() const { return args_[index_]; }
    bool is(std::string_view option) const { return current() == option; }
    /// An option: "-" followed by something ("-" alone is a plain argument).
    bool isOption() const { return current().size() > 1 && current()[0] == '-'; }

    /// The current option's value, consumed.
    const std::string& value();
    // Each typed reader copies the option's name before value() moves past it.
    long integer(long lo, long hi) {
        const std::string opt = current();
        return parseInteger(opt, value(), lo, hi);
    }
    double number(double lo, double hi) {
        const std::string opt = current();
        return parseNumber(opt, value(), lo, hi);
    }
    bool onOff() {
        const std::string opt = current();
        return parseOnOff(opt, value());
    }
    std::pair<int, int> size(int lo, int hi) {
        const std::string opt = current();
        return parseSize(opt, value(), lo, hi);
    }
    template <class E>
    E choice() {
        const std::string opt = current();
        return parseChoice<E>(opt, value());
    }

    /// Throws UsageError "unknown option '...'" for the current argument.
    [[noreturn]] void rejectUnknownOption() const;

private:
    std::vector<std::string> args_;
    std::size_t index_ = static_cast<std::size_t>(-1);
};

}  // namespace tb
