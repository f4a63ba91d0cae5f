// Testbed — parsing scene-file text (see json_text.hpp).
#include "scene_file/json_text.hpp"

#include <set>
#include <vector>

namespace tb::scene_file {

namespace {

// Follows the parser's position so an error thrown while reading a value (a
// number overflow has no position of its own) can name the field, and
// refuses duplicate keys, which JSON allows but which are always a mistake here.
struct PathTracker {
    struct Frame {
        bool isArray = false;
        std::size_t index = 0;
        std::string key;
        std::set<std::string> keys;
    };
    std::vector<Frame> stack;
    std::string duplicate;

    std::string path() const {
        std::string p;
        for (const auto& f : stack) {
            if (f.isArray) {
                p += '[';
                p += std::to_string(f.index);
                p += ']';
            } else if (!f.key.empty()) {
                if (!p.empty()) p += '.';
                p += f.key;
            }
        }
        return p;
    }
    void valueDone() {
        if (!stack.empty() && stack.back().isArray) ++stack.back().index;
    }
};

struct DuplicateKey {};

}  // namespace

json parseJson(const std::string& text, const std::string& file) {
    PathTracker tr;
    auto cb = [&tr](int, json::parse_event_t ev, json& parsed) -> bool {
        switch (ev) {
            case json::parse_event_t::object_start: tr.stack.push_back({false, 0, {}, {}}); break;
            case json::parse_event_t::array_start: tr.stack.push_back({true, 0, {}, {}}); break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                tr.stack.pop_back();
                tr.valueDone();
                break;
            case json::parse_event_t::key: {
                std::string k = parsed.get<std::string>();
                auto& f = tr.stack.back();
                f.key = k;
                if (!f.keys.insert(k).second) {
                    tr.duplicate = k;
                    throw DuplicateKey{};
                }
                break;
            }
            case json::parse_event_t::value: tr.valueDone(); break;
        }
        return true;
    };
    Loc root{&file, {}};
    try {
        return json::parse(text, cb);
    } catch (const DuplicateKey&) {
        fail(Loc{&file, tr.path()}, "duplicate field '" + tr.duplicate + "'");
    } catch (const json::parse_error& e) {
        fail(root, std::string("malformed JSON: ") + e.what());
    } catch (const json::out_of_range& e) {
        // 406: "number overflow parsing '1e999'" — a number not representable as a double.
        fail(Loc{&file, tr.path()}, std::string("not a finite number (") + e.what() + ")");
    } catch (const json::exception& e) {
        fail(root, std::string("invalid JSON: ") + e.what());
    }
}

}  // namespace tb::scene_file
