# Which files the packaged kerf loads under qemu-user (LD_DEBUG=libs): the
# loader and the C and C++ runtimes from the cross toolchain's root (qemu's
# -L), only libmodbus and libgpiod from the extracted arm64 packages. A libc6
# of the target installed through multiarch (/lib/aarch64-linux-gnu) would be
# picked up instead of the cross toolchain's, and fail this.
#   cmake -DKERF=<unpacked kerf> -DEMULATOR=list -DTARGET_ROOT=/usr/<triple>
#         -DTARGET_LIBS=<build/_sysroot/<triple>> -P check_cross_loader.cmake
cmake_minimum_required(VERSION 3.25)
execute_process(COMMAND ${EMULATOR} -E LD_DEBUG=libs ${KERF} --version
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "^kerf ")
  message(FATAL_ERROR "kerf --version under ${EMULATOR} failed (${rc}):\n${out}${err}")
endif()
string(REGEX MATCHALL "calling init: [^\n]+" inits "${err}")
set(seen "")
foreach(line IN LISTS inits)
  string(REGEX REPLACE "calling init: " "" path "${line}")
  get_filename_component(name ${path} NAME)
  if(name MATCHES "^lib(modbus|gpiod)\\.so")
    if(NOT path MATCHES "^${TARGET_LIBS}/")
      message(FATAL_ERROR "${name} loaded from ${path}, not from ${TARGET_LIBS}")
    endif()
  elseif(path MATCHES "^${TARGET_LIBS}/" OR NOT EXISTS ${TARGET_ROOT}${path})
    message(FATAL_ERROR "${name} loaded from ${path}, not from the cross toolchain's ${TARGET_ROOT}")
  endif()
  message(STATUS "${name}: ${path}")
  list(APPEND seen ${name})
endforeach()
foreach(name libc.so.6 libstdc++.so.6 libmodbus.so.5 libgpiod.so.2)
  if(NOT name IN_LIST seen)
    message(FATAL_ERROR "${name} was not loaded:\n${err}")
  endif()
endforeach()
