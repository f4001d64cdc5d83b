# Cross build for s390x Linux (big-endian, LP64), run under qemu-user:
# the whole CTest suite on a big-endian CPU (scripts/bigendian.sh).
#
#   cmake -S . -B build-s390x -DCMAKE_TOOLCHAIN_FILE=cmake/s390x-toolchain.cmake
#
# Needs gcc-s390x-linux-gnu, libc6-dev-s390x-cross, qemu-user and the Rust
# target s390x-unknown-linux-gnu (scripts/setup.sh installs all of them).
# The library is built with cargo --target s390x-unknown-linux-gnu
# (COP_RUST_TARGET); test programs run through CMAKE_CROSSCOMPILING_EMULATOR.
# Sanitizers default to off (COP_SANITIZERS): they are not available for
# programs run under qemu-user.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR s390x)

set(CMAKE_C_COMPILER s390x-linux-gnu-gcc)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-s390x;-L;/usr/s390x-linux-gnu)

set(CMAKE_FIND_ROOT_PATH /usr/s390x-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

set(COP_RUST_TARGET s390x-unknown-linux-gnu CACHE STRING "Rust target triple of the library")
