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
# the C++ exception runtime (including ARM EHABI's cleanup entry), thread-safe
# statics and static destructors (both need an OS runtime), C allocation
# (also newlib's reentrant _*_r forms), stdio (also glibc's _FORTIFY_SOURCE
# __*_chk forms, which Ubuntu's compilers emit by default), glibc's assert,
# and common system calls (also newlib's _write, _sbrk and the like).
set(banned
  "_Znw[a-zA-Z0-9_]*" "_Zna[a-zA-Z0-9_]*" "_Zdl[a-zA-Z0-9_]*" "_Zda[a-zA-Z0-9_]*"
  "__cxa_[a-z_]*throw[a-z_]*" "__cxa_allocate_exception" "__cxa_begin_catch"
  "__cxa_end_catch" "__cxa_end_cleanup" "__gxx_personality_v0" "_Unwind_Resume"
  "__cxa_guard_acquire" "__cxa_guard_release" "__cxa_guard_abort" "__cxa_atexit" "atexit"
  "malloc" "calloc" "realloc" "free" "aligned_alloc" "posix_memalign"
  "_malloc_r" "_calloc_r" "_realloc_r" "_free_r"
  "printf" "fprintf" "sprintf" "snprintf" "vprintf" "vfprintf" "vsprintf" "vsnprintf"
  "puts" "fputs" "putchar" "fputc" "putc"
  "__printf_chk" "__fprintf_chk" "__sprintf_chk" "__snprintf_chk" "__vfprintf_chk"
  "__vsnprintf_chk" "__assert_fail"
  "fopen" "fclose" "fread" "fwrite" "fflush" "stdout" "stderr" "stdin" "_impure_ptr"
  "open" "read" "write" "close" "lseek" "ioctl" "mmap" "sbrk" "exit" "_exit" "abort"
  "_open" "_read" "_write" "_close" "_lseek" "_fstat" "_isatty" "_sbrk" "_kill" "_getpid")
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
