# Wraps deposition_coords.glsl + curtain_emission.glsl in a GLSL 4.50 fragment shader that calls the public
# functions, and compiles it with glslangValidator.
file(MAKE_DIRECTORY ${WORK_DIR})
file(READ ${SHADER_DIR}/deposition_coords.glsl coords)
file(READ ${SHADER_DIR}/curtain_emission.glsl sampler)
set(file ${WORK_DIR}/deposition.frag)
file(WRITE ${file} "#version 450 core\n#define real float\n${coords}\n${sampler}\n"
     "layout(location = 0) out vec4 color;\n"
     "void main() {\n  float h = 60.0 + gl_FragCoord.y;\n  float e = 0.5 + gl_FragCoord.x / 10.0;\n"
     "  color = vec4(curtainEmissionRgbPerKm(h, int(e)), 1.0);\n}\n")
execute_process(COMMAND ${VALIDATOR} ${file} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "shaders/aurora does not compile as GLSL:\n${output}")
endif()
message(STATUS "shaders/aurora: compiles as GLSL 4.50")
