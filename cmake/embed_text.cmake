# Embeds text files into a generated C++ source, at build time, with nothing
# but CMake (no xxd, no runtime file lookup): each file becomes a byte array
# and a std::string_view over it. Run as a script:
#   cmake -DOUTPUT=out.cpp -DINCLUDE=render/viewer/assets.hpp
#         -DNAMESPACE=gridlock::viewer -DNAMES=a|b -DFILES=/p/a.html|/p/b.js
#         [-DFORBID=b=</script|b=<!--] -P embed_text.cmake
# NAMES[i] is the string_view defined for FILES[i] (declared extern in
# INCLUDE). FORBID: NAME=TEXT pairs, a text the file embedded as NAME may not
# contain (compared case-insensitively); the build stops naming the file,
# e.g. "</script" in inlined JavaScript would end the page's script element.
foreach(var OUTPUT INCLUDE NAMESPACE NAMES FILES)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "embed_text.cmake: ${var} is not set")
  endif()
endforeach()
string(REPLACE "|" ";" names "${NAMES}")
string(REPLACE "|" ";" files "${FILES}")
string(REPLACE "|" ";" forbid "${FORBID}")
list(LENGTH names n_names)
list(LENGTH files n_files)
if(NOT n_names EQUAL n_files)
  message(FATAL_ERROR "embed_text.cmake: ${n_names} names for ${n_files} files")
endif()

set(body "")
math(EXPR last "${n_files} - 1")
foreach(i RANGE ${last})
  list(GET names ${i} name)
  list(GET files ${i} file)
  file(READ "${file}" text)
  string(TOLOWER "${text}" lower)
  foreach(rule ${forbid})
    string(FIND "${rule}" "=" eq)
    string(SUBSTRING "${rule}" 0 ${eq} rule_name)
    math(EXPR eq "${eq} + 1")
    string(SUBSTRING "${rule}" ${eq} -1 bad)
    if(NOT rule_name STREQUAL name)
      continue()
    endif()
    string(TOLOWER "${bad}" bad_lower)
    string(FIND "${lower}" "${bad_lower}" at)
    if(NOT at EQUAL -1)
      # The reason first: CMake wraps long messages, and the path can be long.
      message(FATAL_ERROR "refused \"${bad}\" (it cannot be embedded here) in ${file}")
    endif()
  endforeach()
  file(READ "${file}" hex HEX)
  if(hex STREQUAL "")
    message(FATAL_ERROR "${file}: empty")
  endif()
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
  # Sixteen bytes a line.
  string(REPEAT "0x[0-9a-f][0-9a-f]," 16 line)
  string(REGEX REPLACE "(${line})" "\\1\n" bytes "${bytes}")
  get_filename_component(shown "${file}" NAME)
  string(APPEND body "// ${shown}\nconst unsigned char ${name}_bytes[] = {\n${bytes}};\n")
  string(APPEND defs "const std::string_view ${name}(reinterpret_cast<const char*>(${name}_bytes), sizeof ${name}_bytes);\n")
endforeach()

set(out "// Generated at build time by cmake/embed_text.cmake: do not edit; edit the\n")
string(APPEND out "// embedded files instead.\n#include \"${INCLUDE}\"\n\nnamespace ${NAMESPACE} {\nnamespace {\n${body}}  // namespace\n\n${defs}}  // namespace ${NAMESPACE}\n")
# Written only when it changes, so an unchanged input recompiles nothing.
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
  if(old STREQUAL out)
    return()
  endif()
endif()
file(WRITE "${OUTPUT}" "${out}")
