// Mathematical constants, defined once for every shader and for the C++ code that compiles shader
// text (src/common/glsl.h: `real` is float on the GPU, float or double there). The C++ code's own
// are in src/physics/constants.h.
const real kPi = real(3.14159265358979323846);
