# ptpgenFunctions.cmake: ptpgen_generate(), shared by add_subdirectory(ptpgen) and find_package(ptpgen).
# It runs the executable target ptpgen::ptpgen at build time; the file is remade when ptpgen or the command changes.
include_guard(GLOBAL)

# ptpgen_generate(<output> DEGREE <d> TARGET <t> [DOMAIN quad|triangle] [OPTIONS <ptpgen options>...])
# Writes <output> (relative paths are under CMAKE_CURRENT_BINARY_DIR) with
# `ptpgen --degree <d> --target <t> [--domain <dom>] <options> -o <output>`. Name the output as a
# source of a target, or add it to one with add_custom_target(... DEPENDS <output>), to build it.
function(ptpgen_generate output)
  cmake_parse_arguments(PARSE_ARGV 1 PG "" "DEGREE;TARGET;DOMAIN" "OPTIONS")
  if(PG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "ptpgen_generate: unexpected arguments: ${PG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT PG_DEGREE OR NOT PG_TARGET)
    message(FATAL_ERROR "ptpgen_generate(${output}): DEGREE and TARGET are required")
  endif()
  if(NOT TARGET ptpgen::ptpgen)
    message(FATAL_ERROR "ptpgen_generate: no target ptpgen::ptpgen (add_subdirectory or find_package ptpgen first)")
  endif()
  if(NOT IS_ABSOLUTE "${output}")
    set(output "${CMAKE_CURRENT_BINARY_DIR}/${output}")
  endif()
  set(args --degree ${PG_DEGREE} --target ${PG_TARGET})
  if(PG_DOMAIN)
    list(APPEND args --domain ${PG_DOMAIN})
  endif()
  list(APPEND args ${PG_OPTIONS})
  # The command is kept in a file rewritten only when it changes: a new option or degree
  # remakes the output with every generator.
  string(MAKE_C_IDENTIFIER "${output}" stamp)
  set(stamp "${CMAKE_CURRENT_BINARY_DIR}/ptpgen_cmd/${stamp}.txt")
  set(cmd "${args}")
  if(EXISTS "${stamp}")
    file(READ "${stamp}" old)
  else()
    set(old "")
  endif()
  if(NOT old STREQUAL cmd)
    file(WRITE "${stamp}" "${cmd}")
  endif()
  set(deps "$<TARGET_FILE:ptpgen::ptpgen>" "${stamp}")
  get_target_property(real ptpgen::ptpgen ALIASED_TARGET)
  if(real)
    list(APPEND deps ${real})
  endif()
  add_custom_command(
    OUTPUT "${output}"
    COMMAND "$<TARGET_FILE:ptpgen::ptpgen>" ${args} -o "${output}"
    DEPENDS ${deps}
    COMMENT "ptpgen ${args} -o ${output}"
    VERBATIM)
endfunction()
