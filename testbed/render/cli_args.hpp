// Testbed — argument parsing shared by `render` and `view`.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tb {

/// The value after option args[i] (advancing i); std::invalid_argument when it is missing.
inline const std::string& optionValue(const std::vector<std::string>& args, std::size_t& i) {
    if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + ": missing value");
    return args[++i];
}

/// The whole of `value` as an integer; std::invalid_argument naming `flag` otherwise.
inline int parseIntArg(const std::string& flag, const std::string& value) {
    try {
        std::size_t used = 0;
        int v = std::stoi(value, &used);
        if (used == value.size()) return v;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument(flag + ": expected an integer, got '" + value + "'");
}

/// "WxH" as (W, H), each at least `minimum` pixels.
inline std::pair<int, int> parseSizeArg(const std::string& flag, const std::string& value, int minimum) {
    auto x = value.find('x');
    if (x == std::string::npos) throw std::invalid_argument(flag + ": expected WxH, got '" + value + "'");
    int w = parseIntArg(flag, value.substr(0, x)), h = parseIntArg(flag, value.substr(x + 1));
    if (w < minimum || h < minimum)
        throw std::invalid_argument(flag + ": each side must be at least " + std::to_string(minimum) + " pixels");
    return {w, h};
}

}  // namespace tb
