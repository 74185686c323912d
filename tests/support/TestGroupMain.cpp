// The main of a test group (TestMain.h): `<group> <test> [Qt Test arguments]` runs the Qt Test
// class that the file <test>.cpp registered, with the arguments after the name, as that file's
// own program would; `<group> --list-tests` lists the tests it holds.
#include "TestRegistry.h"

#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace stepdeck::test {
namespace {

struct Registry
{
    std::map<std::string, TestRunner> runners;
    std::vector<std::string> duplicates; // a name registered twice: refused in main
};

Registry& registry()
{
    static Registry instance;
    return instance;
}

std::string baseName(const char* sourceFile)
{
    std::string name(sourceFile);
    const size_t slash = name.find_last_of("/\\");
    if (slash != std::string::npos)
        name.erase(0, slash + 1);
    const size_t dot = name.rfind('.');
    if (dot != std::string::npos)
        name.erase(dot);
    return name;
}

} // namespace

bool registerTest(const char* sourceFile, TestRunner run)
{
    const std::string name = baseName(sourceFile);
    if (!registry().runners.emplace(name, run).second)
        registry().duplicates.push_back(name);
    return true;
}

} // namespace stepdeck::test

int main(int argc, char** argv)
{
    using stepdeck::test::registry;
    for (const std::string& name : registry().duplicates) {
        std::fprintf(stderr, "%s: two test files are named %s\n", argv[0], name.c_str());
        return 2;
    }
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s TEST [Qt Test arguments] | --list-tests\n", argv[0]);
        return 2;
    }
    if (std::strcmp(argv[1], "--list-tests") == 0) {
        for (const auto& entry : registry().runners)
            std::printf("%s\n", entry.first.c_str());
        return 0;
    }
    const auto found = registry().runners.find(argv[1]);
    if (found == registry().runners.end()) {
        std::fprintf(stderr, "%s: no test %s here (--list-tests lists them)\n", argv[0], argv[1]);
        return 2;
    }
    // The test sees its own arguments only, and its own name as the program's: Qt takes the
    // application's name from argv[0], and the settings and files a test keeps under that name
    // must not be another test's running beside it (ctest -j).
    std::string program(argv[0]);
    const size_t slash = program.find_last_of('/');
    program = (slash == std::string::npos ? std::string() : program.substr(0, slash + 1)) + argv[1];
    std::vector<char*> arguments{program.data()};
    arguments.insert(arguments.end(), argv + 2, argv + argc);
    arguments.push_back(nullptr);
    return found->second(argc - 1, arguments.data());
}
