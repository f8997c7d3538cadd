# Project-wide target settings, applied per target (no global flags).

# SAGRID_SANITIZE: "" or OFF = none (address,undefined with SAGRID_FUZZ), ON = address,undefined,
# else the list given.
if(SAGRID_FUZZ AND (SAGRID_SANITIZE STREQUAL "" OR SAGRID_SANITIZE STREQUAL "OFF"))
  set(SAGRID_SANITIZERS "address,undefined")
elseif(SAGRID_SANITIZE STREQUAL "" OR SAGRID_SANITIZE STREQUAL "OFF")
  set(SAGRID_SANITIZERS "")
elseif(SAGRID_SANITIZE STREQUAL "ON")
  set(SAGRID_SANITIZERS "address,undefined")
else()
  set(SAGRID_SANITIZERS "${SAGRID_SANITIZE}")
endif()
function(sagrid_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter)
  if(SAGRID_SANITIZERS)
    target_compile_options(${target} PRIVATE -fsanitize=${SAGRID_SANITIZERS} -fno-omit-frame-pointer -g1)
    target_link_options(${target} PRIVATE -fsanitize=${SAGRID_SANITIZERS})
  endif()
  if(SAGRID_FUZZ)  # coverage for libFuzzer in everything the fuzz targets link
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
