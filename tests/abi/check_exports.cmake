# Checks that libmoa.so exports exactly the symbols of tests/abi/exported_symbols.txt, and that
# the list names exactly the functions moa.h declares. Run with
#   cmake -DNM=<nm> -DLIBRARY=<libmoa.so> -DEXPECTED=<list> -DHEADER=<moa.h> -P check_exports.cmake
foreach(var NM LIBRARY EXPECTED HEADER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_exports.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND ${NM} -D --defined-only ${LIBRARY}
  OUTPUT_VARIABLE nm_output RESULT_VARIABLE nm_result ERROR_VARIABLE nm_error)
if(NOT nm_result EQUAL 0)
  message(FATAL_ERROR "${NM} -D --defined-only ${LIBRARY} failed: ${nm_error}")
endif()

# "<address> <type> <name>[@@version]" per line; keep the name.
set(exported "")
string(REPLACE "\n" ";" nm_lines "${nm_output}")
foreach(line IN LISTS nm_lines)
  if(line MATCHES "^[0-9a-fA-F]* *[A-Za-z] ([^ @]+)")
    list(APPEND exported ${CMAKE_MATCH_1})
  endif()
endforeach()
list(SORT exported)

file(STRINGS ${EXPECTED} expected REGEX "^[A-Za-z_]")
list(SORT expected)

file(READ ${HEADER} header_text)
string(REGEX MATCHALL "MOA_API[^;(]*[ *](moa_[a-z0-9_]+)\\(" declarations "${header_text}")
set(declared "")
foreach(declaration IN LISTS declarations)
  string(REGEX MATCH "moa_[a-z0-9_]+\\($" name "${declaration}")
  string(REPLACE "(" "" name "${name}")
  list(APPEND declared ${name})
endforeach()
list(SORT declared)

set(mismatch FALSE)
function(report_difference what actual reference)
  set(extra ${actual})
  set(missing ${reference})
  if(reference)
    list(REMOVE_ITEM extra ${reference})
  endif()
  if(actual)
    list(REMOVE_ITEM missing ${actual})
  endif()
  if(extra OR missing)
    message(SEND_ERROR "${what}\n  unexpected: ${extra}\n  missing: ${missing}")
    set(mismatch TRUE PARENT_SCOPE)
  endif()
endfunction()

report_difference("exported symbols of ${LIBRARY} differ from ${EXPECTED}"
  "${exported}" "${expected}")
report_difference("functions declared in ${HEADER} differ from ${EXPECTED}"
  "${declared}" "${expected}")
if(NOT mismatch)
  list(LENGTH exported n)
  message(STATUS "${n} exported symbols, all as listed in ${EXPECTED}")
endif()
