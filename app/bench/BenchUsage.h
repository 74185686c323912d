#pragma once

namespace stepdeck {
struct ModelInfo;
}

namespace stepdeck::bench {

// stepdeck-bench --help: every mode and option. model: the one the default run measures.
void printUsage(const ModelInfo* model);

} // namespace stepdeck::bench
