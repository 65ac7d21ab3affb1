# Wraps the plasma's shared kernels (shaders/components/plasma) in a GLSL 4.50 compute shader that
# calls each of them, and compiles it with glslangValidator: the text the C++ tests run in double
# must also be valid GLSL. Then the GPU step (pic_step.comp) and the Poisson sweeps
# (poisson_sweep.comp) for every dimension and pass.
file(MAKE_DIRECTORY ${WORK_DIR})
set(kernels "")
foreach(module cloud_in_cell electric_field boris_push)
  file(READ ${SHADER_DIR}/${module}.glsl text)
  string(APPEND kernels "${text}\n")
endforeach()
# The TSC weights, which the GPU step does not use, are checked here only.
file(READ ${SHADER_DIR}/triangular_shaped_cloud.glsl shape)
set(file ${WORK_DIR}/plasma_kernels.comp)
file(WRITE ${file} "#version 450 core\n#define real float\nlayout(local_size_x = 64) in;\n${kernels}\n${shape}\n"
     "layout(std430, binding = 0) buffer Particles { vec4 state[]; };\n"
     "void main() {\n  uint p = gl_GlobalInvocationID.x;\n"
     "  vec3 f = cicCellFraction(state[p].xyz);\n"
     "  float rho = cicCornerChargeDensity(-1.0, 1.0, f, 3, 2);\n"
     "  vec3 e = cicCornerField(vec3(centralDifferenceField(rho, 1.0, 0.1)), f, 5, 3);\n"
     "  vec3 o = tscNodeOffset(state[p].xyz);\n"
     "  rho += tscNodeChargeDensity(-1.0, 1.0, o, 13, 3) + tscNearestNode(state[p].xyz).x;\n"
     "  e += tscNodeField(vec3(rho), o, 7, 2);\n"
     "  vec3 v = borisVelocity(state[p].xyz, e, vec3(0.0, 0.0, 1.0), -1.0, 0.1);\n"
     "  state[p] = vec4(leapfrogPosition(state[p].xyz, v, 0.1, vec3(1.0)), cicCornerWeight(f, 1, 1));\n}\n")
execute_process(COMMAND ${VALIDATOR} ${file} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "shaders/components/plasma does not compile as GLSL:\n${output}")
endif()
# A compute shader built from TEXT for every dimension and pass (PASS_DEFINE set to each of the
# remaining arguments), compiled by glslangValidator.
function(check_every_pass name text pass_define)
  foreach(dimension 1 2 3)
    foreach(pass ${ARGN})
      set(file ${WORK_DIR}/${name}_${dimension}_${pass}.comp)
      file(WRITE ${file} "#version 450 core\n#define real float\n#define PLASMA_DIMENSION ${dimension}\n"
           "#define ${pass_define} ${pass}\n#define DISPATCH_INVOCATION gl_GlobalInvocationID\n${text}")
      execute_process(COMMAND ${VALIDATOR} ${file} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
      if(NOT result EQUAL 0)
        message(FATAL_ERROR "${name}.comp (dimension ${dimension}, pass ${pass}) does not compile as GLSL:\n${output}")
      endif()
    endforeach()
  endforeach()
endfunction()
# The GPU step with the kernels before it, as the program assembles them; the Poisson sweeps (a
# module of their own).
file(READ ${SHADER_DIR}/pic_step.comp step)
check_every_pass(pic_step "${kernels}\n${step}" PLASMA_PASS 1 2 3)
file(READ ${SHADER_DIR}/poisson_sweep.comp sweep)
check_every_pass(poisson_sweep "${sweep}" POISSON_PASS 1 2 3 4 5 6)
message(STATUS "shaders/components/plasma: compiles as a GLSL 4.50 compute shader")
