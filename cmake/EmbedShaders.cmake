# Compiles every shaders/<pass>.<stage>.glsl to SPIR-V with glslangValidator and wraps it in a C
# header (<pass>.<stage>.spv.h defining uint32_t <pass>_<stage>_spv[]), so binaries carry their
# shaders. Each shader is rebuilt when it or any shared header in shaders/ changes.
# Optional: INCLUDE dirs also searched for includes (and watched), OUTPUT the folder the headers go to
# under the build tree (default: shaders).
function(embed_shaders target shader_dir)
  cmake_parse_arguments(EMBED "" "OUTPUT" "INCLUDE" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${shader_dir}/*.glsl)
  set(include_flags -I${shader_dir})
  set(header_globs ${shader_dir}/*.h ${shader_dir}/*.glsl.inc)
  foreach(dir ${EMBED_INCLUDE})
    list(APPEND include_flags -I${dir})
    list(APPEND header_globs ${dir}/*.h ${dir}/*.glsl.inc)
  endforeach()
  file(GLOB headers CONFIGURE_DEPENDS ${header_globs})
  if(NOT EMBED_OUTPUT)
    set(EMBED_OUTPUT shaders)
  endif()
  set(out_dir ${CMAKE_BINARY_DIR}/${EMBED_OUTPUT})
  file(MAKE_DIRECTORY ${out_dir})
  set(outputs)
  foreach(source ${sources})
    get_filename_component(file_name ${source} NAME)
    string(REGEX REPLACE "\\.glsl$" "" base ${file_name})
    string(REGEX MATCH "[^.]+$" stage ${base})
    string(REPLACE "." "_" variable ${base})
    set(output ${out_dir}/${base}.spv.h)
    add_custom_command(
      OUTPUT ${output}
      COMMAND ${GLSLANG_VALIDATOR} --quiet --target-env vulkan1.2 -S ${stage} ${include_flags}
              --vn ${variable}_spv -o ${output} ${source}
      DEPENDS ${source} ${headers}
      COMMENT "Compiling shader ${file_name}"
      VERBATIM)
    list(APPEND outputs ${output})
  endforeach()
  add_custom_target(${target}_spirv DEPENDS ${outputs})
  add_library(${target} INTERFACE)
  target_include_directories(${target} INTERFACE ${out_dir})
  add_dependencies(${target} ${target}_spirv)
endfunction()
