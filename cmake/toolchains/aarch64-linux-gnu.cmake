# Cross-compiles for arm64 (aarch64) Linux with Debian's crossbuild-essential-arm64; the target's
# libraries come from Debian multiarch (:arm64 -dev packages in /usr/lib/aarch64-linux-gnu).
# scripts/setup-cross-arm64.sh installs both. Tests and gtest discovery run the arm64 binaries under
# qemu-aarch64-static.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

# Multiarch keeps host and target libraries side by side under /usr, so the root is / and the
# architecture-specific directories come from CMAKE_LIBRARY_ARCHITECTURE. Programs are the host's.
set(CMAKE_FIND_ROOT_PATH /)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config reads only the target's .pc files (and the architecture-independent ones).
set(ENV{PKG_CONFIG_LIBDIR} /usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")

# qemu-aarch64-static without -L: the programs then load /lib/ld-linux-aarch64.so.1 and libc.so.6
# both from libc6:arm64, which the multiarch libraries pull in. With -L /usr/aarch64-linux-gnu the
# loader would come from the cross toolchain's libc (2.36-8cross1 on Debian 12) while libc.so.6
# still comes from libc6:arm64 (2.36-9+deb12u14): a mismatched pair, and every pthread_create
# hangs (docs/DEPLOY.md).
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64-static)
