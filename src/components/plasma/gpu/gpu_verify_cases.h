#pragma once
// The verification cases of `aurorawall plasma verify --device gpu`: langmuir, langmuir-2d, boris and
// exb run with GpuPic (float, compute shaders) in the settings of verify_cases.h and against the same
// expected values from theory, with the step's Poisson solver `solver`. Need a current GL 4.5
// context; shaderDir holds components/plasma/.
#include "components/plasma/gpu/gpu_pic.h"
#include "components/plasma/simulation/verify_cases.h"

#include <string>
#include <vector>

namespace aurorawall::plasma {

std::vector<VerifyRow> verifyLangmuirOnGpu(double plasmaFrequencyTimesDt, const std::string& shaderDir,
                                           GpuPicSolver solver = GpuPicSolver::FftCpu);
std::vector<VerifyRow> verifyLangmuir2DOnGpu(double plasmaFrequencyTimesDt, const std::string& shaderDir,
                                             int cellsPerAxis = 256, GpuPicSolver solver = GpuPicSolver::FftCpu);
// One test particle (weight 0: no charge of its own, so the solver does not matter) in a uniform B,
// or crossed uniform E and B.
std::vector<VerifyRow> verifyBorisOnGpu(double cyclotronFrequencyTimesDt, const std::string& shaderDir,
                                        long steps = 1000);
std::vector<VerifyRow> verifyExBOnGpu(double cyclotronFrequencyTimesDt, const std::string& shaderDir);

} // namespace aurorawall::plasma
