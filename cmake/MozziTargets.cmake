# Settings every Mozzi target shares, applied per target (no directory-wide flags).

# The sanitizers (MOZZI_ASAN, MOZZI_UBSAN): -O1 -g1 -fno-omit-frame-pointer
# whatever the build type (line tables are all a report needs); every
# undefined-behaviour report is fatal.
set(MOZZI_SANITIZE_ONLY "" CACHE STRING
    "With MOZZI_ASAN/MOZZI_UBSAN: a regular expression of the library sources (paths from the source folder, \
e.g. ^core/io/) compiled with the sanitizers; the others keep the build type's flags. Empty: all of them.")
set(_mozzi_sanitize_flags "")
set(_mozzi_sanitize_link "")
if(MOZZI_ASAN)
  list(APPEND _mozzi_sanitize_flags -fsanitize=address)
  list(APPEND _mozzi_sanitize_link -fsanitize=address)
endif()
if(MOZZI_UBSAN)
  list(APPEND _mozzi_sanitize_flags -fsanitize=undefined -fno-sanitize-recover=undefined)
  list(APPEND _mozzi_sanitize_link -fsanitize=undefined)
endif()
if(_mozzi_sanitize_flags)
  # EIGEN_MALLOC_ALREADY_ALIGNED=1: under ASan Eigen switches from malloc to
  # its own over-allocating aligned malloc (its Memory.h tests
  # __SANITIZE_ADDRESS__). With MOZZI_SANITIZE_ONLY, instrumented and plain
  # translation units share Eigen's inline allocation functions, and the
  # linker keeps one copy of each: a matrix allocated by one and freed by the
  # other is a heap-buffer-overflow (found by tire_csv_fuzz). glibc's and
  # ASan's malloc both return 16-byte aligned memory on x86-64, what Eigen's
  # SSE code needs, so every unit uses malloc as the plain build does.
  list(APPEND _mozzi_sanitize_flags -fno-omit-frame-pointer -O1 -g1 -DEIGEN_MALLOC_ALREADY_ALIGNED=1)
endif()

function(mozzi_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_17)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror)
  if(NOT _mozzi_sanitize_flags)
    return()
  endif()
  get_target_property(type ${target} TYPE)
  target_link_options(${target} PRIVATE ${_mozzi_sanitize_link})
  if(MOZZI_SANITIZE_ONLY STREQUAL "" OR type STREQUAL "EXECUTABLE")
    target_compile_options(${target} PRIVATE ${_mozzi_sanitize_flags})
    return()
  endif()
  # A library with a narrowed scope: the matching sources only. The others
  # compile exactly as in the plain build (so ccache has them already).
  get_target_property(sources ${target} SOURCES)
  foreach(s IN LISTS sources)
    if(NOT s MATCHES "\\.cpp$")
      continue()
    endif()
    file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${s})
    if(rel MATCHES "${MOZZI_SANITIZE_ONLY}")
      set_property(SOURCE ${s} TARGET_DIRECTORY ${target} APPEND PROPERTY COMPILE_OPTIONS ${_mozzi_sanitize_flags})
    endif()
  endforeach()
endfunction()

# Qt code stays Qt 6 clean: nothing deprecated before 5.15.
function(mozzi_qt_defaults target)
  target_compile_definitions(${target} PRIVATE QT_DISABLE_DEPRECATED_BEFORE=0x050F00
)
  set_target_properties(${target} PROPERTIES AUTOMOC ON AUTORCC ON AUTOUIC OFF)
endfunction()
