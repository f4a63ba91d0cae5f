// Opens `testbed view` on the code-built test scene; arguments as for
// `testbed view` minus the scene (e.g. --screenshot FILE --frames N --size WxH).
#include <iostream>
#include <string>
#include <vector>

#include "render/viewer.hpp"
#include "test_scene.hpp"

int main(int argc, char** argv) {
    tb::ViewerOptions options;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--screenshot" && i + 1 < argc) {
            options.screenshot = argv[++i];
        } else if (a == "--frames" && i + 1 < argc) {
            options.frames = std::stoi(argv[++i]);
        } else if (a == "--size" && i + 1 < argc) {
            std::string v = argv[++i];
            options.width = std::stoi(v.substr(0, v.find('x')));
            options.height = std::stoi(v.substr(v.find('x') + 1));
        } else {
            std::cerr << "view_probe: unknown argument " << a << "\n";
            return 2;
        }
    }
    std::vector<tb::ViewerScene> scenes = {{"render-test", [] { return tbtest::makeTestScene(); }}};
    return tb::runViewer(scenes, 0, options);
}
