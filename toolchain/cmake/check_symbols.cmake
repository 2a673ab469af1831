# cmake -DNM=<nm> -DLIB=<archive> -P check_symbols.cmake
# Fails (exit 1, naming the symbols) when the archive needs any symbol that a
# freestanding, allocation-free, exception-free core must not use.
if(NOT NM OR NOT LIB)
  message(FATAL_ERROR "usage: cmake -DNM=<nm> -DLIB=<archive> -P check_symbols.cmake")
endif()
execute_process(COMMAND ${NM} -u ${LIB} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} -u ${LIB} failed (${rc})")
endif()

# Mangled names: operator new/delete (all overloads start _Znw/_Zna/_Zdl/_Zda),
# the C++ exception runtime, C allocation, stdio and common system calls.
set(banned
  "_Znw[a-zA-Z0-9_]*" "_Zna[a-zA-Z0-9_]*" "_Zdl[a-zA-Z0-9_]*" "_Zda[a-zA-Z0-9_]*"
  "__cxa_[a-z_]*throw[a-z_]*" "__cxa_allocate_exception" "__cxa_begin_catch"
  "__gxx_personality_v0" "_Unwind_Resume"
  "malloc" "calloc" "realloc" "free" "aligned_alloc" "posix_memalign"
  "printf" "fprintf" "sprintf" "snprintf" "vprintf" "vfprintf" "puts" "fputs" "putchar"
  "fopen" "fclose" "fread" "fwrite" "fflush" "stdout" "stderr" "stdin"
  "open" "read" "write" "close" "ioctl" "mmap" "sbrk" "_sbrk" "exit" "abort")
set(found "")
string(REPLACE "\n" ";" lines "${out}")
foreach(line IN LISTS lines)
  string(STRIP "${line}" line)
  # nm -u prints "U name" (or "w name" for weak references).
  if(line MATCHES "^[Uw] +([^ ]+)$")
    set(sym "${CMAKE_MATCH_1}")
    foreach(pattern IN LISTS banned)
      if(sym MATCHES "^${pattern}(@.*)?$")
        list(APPEND found "${sym}")
      endif()
    endforeach()
  endif()
endforeach()
if(found)
  list(REMOVE_DUPLICATES found)
  foreach(sym IN LISTS found)
    message("banned symbol: ${sym}")
  endforeach()
  message(FATAL_ERROR "${LIB} needs symbols a freestanding core must not use (listed above)")
endif()
message(STATUS "${LIB}: no allocator, exception, stdio or OS symbols")
