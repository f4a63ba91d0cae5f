// Testbed — finding scene files: a name or path to a file, the shipped
// scenes of an assets directory, and where that directory is (see scene_loader.hpp).
#include "scene_loader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tb {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

}  // namespace

std::string resolveScenePath(const std::string& nameOrPath, const std::string& assetsDir) {
    bool looksLikePath = nameOrPath.find('/') != std::string::npos ||
                         (nameOrPath.size() > 5 && nameOrPath.substr(nameOrPath.size() - 5) == ".json");
    std::error_code ec;
    if (looksLikePath) {
        if (!fs::is_regular_file(nameOrPath, ec)) throw SceneError(nameOrPath + ": no such file");
        return nameOrPath;
    }
    std::string dir = assetsDir.empty() ? defaultAssetsDir() : assetsDir;
    if (dir.empty())
        throw SceneError(nameOrPath + ": no assets directory found (give --assets DIR or a path to a scene file)");
    for (const fs::path& p :
         {fs::path(dir) / "scenes" / (nameOrPath + ".json"), fs::path(dir) / (nameOrPath + ".json")})
        if (fs::is_regular_file(p, ec)) return p.string();
    throw SceneError(nameOrPath + ": no such scene in " + (fs::path(dir) / "scenes").string() +
                     " (see `testbed list`)");
}

SceneDesc loadSceneDesc(const std::string& nameOrPath, const std::string& assetsDir) {
    std::string path = resolveScenePath(nameOrPath, assetsDir);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open file");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw SceneError(path + ": read error");
    return parseSceneDesc(ss.str(), path, fs::path(path).stem().string());
}

std::vector<std::pair<std::string, std::string>> listScenes(const std::string& assetsDir) {
    std::vector<std::pair<std::string, std::string>> out;
    std::string dir = assetsDir.empty() ? defaultAssetsDir() : assetsDir;
    if (dir.empty()) return out;
    std::error_code ec;
    fs::path scenes = fs::path(dir) / "scenes";
    if (!fs::is_directory(scenes, ec)) scenes = dir;
    for (const auto& entry : fs::directory_iterator(scenes, ec)) {
        const fs::path& p = entry.path();
        std::string fname = p.filename().string();
        if (p.extension() != ".json" || fname.ends_with(".schema.json")) continue;
        std::string description;
        try {
            std::ifstream in(p, std::ios::binary);
            std::ostringstream ss;
            ss << in.rdbuf();
            json j = json::parse(ss.str());
            if (j.is_object() && j.contains("description") && j["description"].is_string())
                description = j["description"].get<std::string>();
        } catch (const std::exception& e) {
            description = std::string("(invalid: ") + e.what() + ")";
        }
        out.emplace_back(p.stem().string(), description);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string defaultAssetsDir() {
    std::vector<fs::path> candidates;
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        fs::path d = exe.parent_path();
        candidates.push_back(d / "assets");
        candidates.push_back(d / ".." / "assets");
        candidates.push_back(d / ".." / "share" / "impulse2d" / "assets");
    }
#ifdef TB_SOURCE_ASSETS_DIR
    candidates.push_back(TB_SOURCE_ASSETS_DIR);
#endif
    for (const fs::path& c : candidates)
        if (fs::is_directory(c / "scenes", ec)) return fs::weakly_canonical(c, ec).string();
    return {};
}

}  // namespace tb
