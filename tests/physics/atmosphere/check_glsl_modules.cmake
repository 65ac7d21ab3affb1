# Wraps each shared module (with physics/constants.glsl and airmass_common.glsl before it; "a.glsl+b.glsl" compiles several in order) in a GLSL 4.50 fragment shader
# that calls its public function, and compiles it with glslangValidator.
file(MAKE_DIRECTORY ${WORK_DIR})
file(READ ${SHADER_DIR}/../constants.glsl constants)
file(READ ${SHADER_DIR}/airmass_common.glsl common)
set(calls
  "airmass_lawlor.glsl|airmassLawlorWinitzki(o, d, 0.0, 100.0, 8.0, 6371.0) + airmassLawlorErfcx(o, d, 0.0, 100.0, 8.0, 6371.0)"
  "airmass_tectonics.glsl|airmassTectonics(o, d, 0.0, 100.0, 8.0, 6371.0)"
  "airmass_chapman.glsl|airmassChapmanSchueler(o, d, 0.0, 100.0, 8.0, 6371.0) + airmassChapmanHdrp(o, d, 0.0, 100.0, 8.0, 6371.0) + airmassChapmanAsymptotic(o, d, 0.0, 100.0, 8.0, 6371.0)"
  "airmass_march.glsl|airmassMarch16(o, d, 0.0, 100.0, 8.0, 6371.0)"
  "airmass_chapman.glsl+sky.glsl|skySingleScattering(o, d, 1e30, SkyAtmosphere(6371.0, 6471.0, 8.0, vec3(5.8e-3, 13.5e-3, 33.1e-3)), 2, lightDirections, lightIlluminance, 16).xyzz + skySingleScatteringNested(o, d, 1e30, SkyAtmosphere(6371.0, 6471.0, 8.0, vec3(5.8e-3, 13.5e-3, 33.1e-3)), 8, lightDirections, lightIlluminance, 16, 8).xyzz")
foreach(entry IN LISTS calls)
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 module)
  list(GET parts 1 call)
  string(REPLACE "+" ";" files "${module}")
  set(body "")
  foreach(part IN LISTS files)
    file(READ ${SHADER_DIR}/${part} text)
    string(APPEND body "${text}\n")
  endforeach()
  string(CONCAT shader "#version 450 core\n#define real float\n${constants}\n${common}\n${body}\n"
             "layout(location = 0) out vec4 color;\n"
             "uniform vec3 lightDirections[8];\nuniform vec3 lightIlluminance[8];\n"
             "void main() {\n  vec3 o = vec3(0.0, 0.0, 6372.0 + gl_FragCoord.x);\n  vec3 d = normalize(vec3(1.0, 0.0, gl_FragCoord.y));\n"
             "  color = vec4(${call});\n}\n")
  set(file ${WORK_DIR}/${module}.frag)
  file(WRITE ${file} "${shader}")
  execute_process(COMMAND ${VALIDATOR} ${file} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${module} does not compile as GLSL:\n${output}")
  endif()
  message(STATUS "${module}: compiles as GLSL 4.50")
endforeach()
