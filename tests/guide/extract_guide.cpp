// Turns every ```cpp block of docs/guide.md into part of one program, so that
// the guide's examples are compiled and run as a test (tests/guide/CMakeLists.txt).
//
// Each block is a complete example with its own `int main()`. Its #include
// lines are gathered at the top of the program; the rest is placed in a
// namespace of its own (guide_block_N), where `main` is an ordinary function,
// and the program's main runs every block's main in order and fails when one
// returns non-zero or throws. Usage: extract_guide GUIDE.md OUT.cpp
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: extract_guide GUIDE.md OUT.cpp\n";
        return 2;
    }
    std::ifstream in(argv[1]);
    if (!in) {
        std::cerr << "extract_guide: cannot read " << argv[1] << "\n";
        return 1;
    }
    struct Block {
        int line = 0;
        std::string body;
    };
    std::vector<Block> blocks;
    std::vector<std::string> includes;
    std::set<std::string> seen;
    std::string line;
    int lineNo = 0;
    bool inside = false;
    while (std::getline(in, line)) {
        ++lineNo;
        if (!inside && line.rfind("```cpp", 0) == 0) {
            inside = true;
            blocks.push_back({lineNo + 1, ""});
            continue;
        }
        if (inside && line.rfind("```", 0) == 0) {
            inside = false;
            continue;
        }
        if (!inside) continue;
        if (line.rfind("#include", 0) == 0) {
            if (seen.insert(line).second) includes.push_back(line);
            continue;
        }
        blocks.back().body += line + "\n";
    }
    if (inside) {
        std::cerr << "extract_guide: " << argv[1] << ": a ```cpp block is not closed\n";
        return 1;
    }
    if (blocks.empty()) {
        std::cerr << "extract_guide: " << argv[1] << " has no ```cpp block\n";
        return 1;
    }
    std::ostringstream out;
    out << "// Generated from " << argv[1] << " by extract_guide: do not edit.\n";
    for (const std::string& inc : includes) out << inc << "\n";
    out << "#include <exception>\n#include <iostream>\n\n";
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        out << "namespace guide_block_" << i + 1 << " {\n";
        out << "#line " << blocks[i].line << " \"" << argv[1] << "\"\n";
        out << blocks[i].body << "}  // namespace guide_block_" << i + 1 << "\n\n";
    }
    out << "int main() {\n    int failed = 0;\n";
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        out << "    try {\n        if (guide_block_" << i + 1 << "::main() != 0) {\n"
            << "            std::cerr << \"guide block at line " << blocks[i].line << " returned non-zero\\n\";\n"
            << "            ++failed;\n        }\n    } catch (const std::exception& e) {\n"
            << "        std::cerr << \"guide block at line " << blocks[i].line << " threw: \" << e.what() << \"\\n\";\n"
            << "        ++failed;\n    }\n";
    }
    out << "    std::cout << \"" << blocks.size() << " guide blocks run, \" << failed << \" failed\\n\";\n"
        << "    return failed == 0 ? 0 : 1;\n}\n";
    std::ofstream o(argv[2]);
    o << out.str();
    return o ? 0 : 1;
}
