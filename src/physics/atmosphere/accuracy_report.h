#pragma once
// The accuracy and shader cost of the airmass methods and of the several-lights sky, as
// docs/ACCURACY.md shows them (`aurorawall accuracy --airmass | --sky`).
#include "physics/atmosphere/airmass.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace aurorawall::physics::atmosphere {

// An airmass method's GLSL (AirmassMethod::glslFunction) evaluated once per ray in a compute shader on
// the current GL 4.5 context, the float results read back (the rays' inputs rounded to float).
// Throws gl::ShaderError when the shader does not compile.
std::vector<double> evaluateAirmassInShader(const std::string& glslFunction, const std::vector<AirmassRay>& rays);

struct AccuracyReportSettings {
    int airmassRepeat = 1024; // airmass evaluations per shader invocation
    int copies = 0;           // the work per dispatch, in copies of the item set; 0: 1 on llvmpipe, 64 on a GPU
    int viewSteps = 16;       // sky: outer march steps M
    int lightSteps = 8;       // sky: nested-march steps K per light
};

// On the current GL 4.5 context: times the shared GLSL modules in a compute shader, reads their float
// results back and compares them, and the CPU float32/float64 evaluations of the same text, with the
// double reference; prints the table. Throws when a shader does not compile.
void printAirmassAccuracy(const AccuracyReportSettings& settings, std::ostream& out);
void printSkyAccuracy(const AccuracyReportSettings& settings, std::ostream& out);

// A table of `aurorawall accuracy --OPTION` that takes no scene: one of the two above.
struct ShaderTable {
    const char* option; // without the dashes
    const char* help;   // its line in `accuracy --help`
    void (*print)(const AccuracyReportSettings& settings, std::ostream& out);
};

// The airmass methods, then the several-lights sky.
const std::vector<ShaderTable>& shaderTables();

} // namespace aurorawall::physics::atmosphere
