# Finds what kin5kins, kin5's LinuxCNC kinematics module, is built with: LinuxCNC's
# Makefile.modinc and headers (Debian: linuxcnc-uspace-dev) and its user-space HAL library.
# Sets KIN5_LINUXCNC_FOUND, KIN5_LINUXCNC_MODINC, KIN5_LINUXCNC_INCLUDE_DIR, KIN5_LINUXCNC_HAL_LIBRARY,
# KIN5_LINUXCNC_RTLIB_DIR (where LinuxCNC loads modules from, RTLIBDIR of Makefile.modinc)
# and KIN5_LINUXCNC_MODULE_DIR, where kin5kins.so is installed: LinuxCNC's module directory
# (RTLIBDIR of Makefile.modinc) relative to /usr, so that `cmake --install --prefix /usr` puts it
# where LinuxCNC loads modules from and any other prefix keeps it under that prefix.
find_file(KIN5_LINUXCNC_MODINC Makefile.modinc PATHS /usr/share/linuxcnc /usr/local/share/linuxcnc
          DOC "LinuxCNC's Makefile.modinc (linuxcnc-uspace-dev)")
find_path(KIN5_LINUXCNC_INCLUDE_DIR kinematics.h PATH_SUFFIXES linuxcnc DOC "LinuxCNC's headers")
find_library(KIN5_LINUXCNC_HAL_LIBRARY linuxcnchal DOC "LinuxCNC's user-space HAL library")
set(KIN5_LINUXCNC_FOUND FALSE)
if(KIN5_LINUXCNC_MODINC AND KIN5_LINUXCNC_INCLUDE_DIR AND KIN5_LINUXCNC_HAL_LIBRARY)
  set(KIN5_LINUXCNC_FOUND TRUE)
  file(STRINGS ${KIN5_LINUXCNC_MODINC} rtlib REGEX "^RTLIBDIR :=")
  list(GET rtlib -1 rtlib)
  string(REGEX REPLACE "^RTLIBDIR :=[ \t]*" "" rtlib "${rtlib}")
  set(KIN5_LINUXCNC_RTLIB_DIR "${rtlib}")
  string(REGEX REPLACE "^/usr/" "" rtlib "${rtlib}")
  set(KIN5_LINUXCNC_MODULE_DIR "${rtlib}" CACHE STRING "Where kin5kins.so is installed, relative to the prefix")
endif()
