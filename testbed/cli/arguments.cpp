// Testbed — the command-line argument reader (see arguments.hpp).
#include "cli/arguments.hpp"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <ostream>

namespace tb {

int reportUsageError(std::ostream& err, std::string_view command, const UsageError& error, std::string_view hint) {
    err << "testbed " << command << ": " << error.what() << "\n" << hint;
    return kUsageExitCode;
}

long parseInteger(std::string_view option, const std::string& text, long lo, long hi) {
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi) {
        // An upper bound of INT_MAX is only the type's: not worth showing.
        const std::string range = hi == INT_MAX ? "of at least " + std::to_string(lo)
                                                : "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
        throw UsageError(std::string(option) + ": expected an integer " + range + ", got '" + text + "'");
    }
    return v;
}

double parseNumber(std::string_view option, const std::string& text, double lo, double hi) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
        throw UsageError(std::string(option) + ": expected a number in [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "], got '" + text + "'");
    return v;
}

bool parseOnOff(std::string_view option, const std::string& text) {
    if (text == "on") return true;
    if (text == "off") return false;
    throw UsageError(std::string(option) + ": expected on or off, got '" + text + "'");
}

std::pair<int, int> parseSize(std::string_view option, const std::string& text, int lo, int hi) {
    const auto x = text.find('x');
    const auto wholeInt = [&](const std::string& side, long& v) {
        char* end = nullptr;
        errno = 0;
        v = std::strtol(side.c_str(), &end, 10);
        return !side.empty() && *end == '\0' && errno != ERANGE;
    };
    long w = 0, h = 0;
    if (x == std::string::npos || !wholeInt(text.substr(0, x), w) || !wholeInt(text.substr(x + 1), h))
        throw UsageError(std::string(option) + ": expected WxH, got '" + text + "'");
    if (w < lo || h < lo || w > hi || h > hi) {
        const std::string bounds = hi == INT_MAX ? "at least " + std::to_string(lo)
                                                 : "from " + std::to_string(lo) + " to " + std::to_string(hi);
        throw UsageError(std::string(option) + ": each side must be " + bounds + " pixels, got '" + text + "'");
    }
    return {static_cast<int>(w), static_cast<int>(h)};
}

const std::string& ArgReader::value() {
    if (index_ + 1 >= args_.size()) throw UsageError(current() + " needs a value");
    return args_[++index_];
}

void ArgReader::rejectUnknownOption() const { throw UsageError("unknown option '" + current() + "'"); }

}  // namespace tb
