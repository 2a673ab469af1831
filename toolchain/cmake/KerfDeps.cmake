# Third-party code from Debian packages.

# Header-only packages live in the host's /usr/include, which a cross compiler
# must not search (it would find x86-64 glibc headers). Expose just the one
# package's header folder through a link in the build tree instead.
function(kerf_header_only name header_dir)
  if(NOT EXISTS /usr/include/${header_dir})
    message(FATAL_ERROR "/usr/include/${header_dir} not found: run toolchain/setup.sh")
  endif()
  set(dir ${CMAKE_BINARY_DIR}/_headers/${name})
  file(MAKE_DIRECTORY ${dir})
  file(CREATE_LINK /usr/include/${header_dir} ${dir}/${header_dir} SYMBOLIC)
  add_library(kerf_dep_${name} INTERFACE)
  target_include_directories(kerf_dep_${name} SYSTEM INTERFACE ${dir})
  add_library(kerf::${name} ALIAS kerf_dep_${name})
endfunction()
