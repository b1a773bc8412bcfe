# The Debian packages, two from one build (one per install component, see CMakeLists.txt):
#   ydscope-cli_<version>_<arch>.deb  the headless program, its man pages, completion, udev rule
#                                     and serve unit; what a robot without a screen installs
#   ydscope_<version>_<arch>.deb      the window, its menu entry, icons and AppStream data; depends
#                                     on ydscope-cli of the same version
# Each package's Depends are what dpkg-shlibdeps finds its own binaries link (so they follow the
# build machine's libraries), plus what is loaded at run time. dpkg-shlibdeps looks at each
# package's files alone, so ydscope-cli gets no GL, GLFW or Mesa.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ydscope)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "ydscope maintainers <ydscope@lists.invalid>")
set(CPACK_DEB_COMPONENT_INSTALL ON)
# One package per component, whatever groups may come.
set(CPACK_COMPONENTS_GROUPING IGNORE)
set(CPACK_COMPONENTS_ALL cli)
if(TARGET ydscope)
  list(APPEND CPACK_COMPONENTS_ALL app)
endif()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # ydscope-cli_0.1.0_amd64.deb, ydscope_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
# No CPACK_PACKAGE_DESCRIPTION_SUMMARY and no package-wide Depends or Recommends: CPack would give
# them to both packages. Each description's first line is its summary; CPack indents the rest.

set(CPACK_DEBIAN_CLI_PACKAGE_NAME ydscope-cli)
set(CPACK_DEBIAN_CLI_DESCRIPTION "headless toolkit for YDLIDAR G1, G6 and TG lidars
ydscope-cli works a YDLIDAR G1, G6 or TG-series (TG15, TG30, TG50) 2D spinning
lidar without a screen: it lists ports, queries a device, prints laps as JSON
lines, records, replays and decodes sessions, exports MCAP, checks a unit
against a target and serves the live scan to Foxglove (a systemd unit,
ydscope-serve@.service, runs that on boot). It runs a virtual lidar for tests.
A udev rule gives the logged-in user the lidar's USB-serial port.
.
The window, ydscope, is in the ydscope package.")
# Applies the udev rule to bridges already plugged in; the rule is in this package.
set(CPACK_DEBIAN_CLI_PACKAGE_CONTROL_EXTRA ${CMAKE_CURRENT_SOURCE_DIR}/postinst)
# Up to 0.1.0 one package, ydscope, held everything, ydscope-cli's files included: this takes them
# over from it (dpkg would refuse to overwrite them otherwise). The new ydscope holds none of them,
# so its own 0.1.0 is not affected.
set(CPACK_DEBIAN_CLI_PACKAGE_REPLACES "ydscope (<= 0.1.0)")

set(CPACK_DEBIAN_APP_PACKAGE_NAME ydscope)
set(CPACK_DEBIAN_APP_DESCRIPTION "real-time viewer for YDLIDAR G1, G6 and TG lidars
ydscope shows the scan of a YDLIDAR G1, G6 or TG-series (TG15, TG30, TG50) 2D
spinning lidar live: health bits, device information, the real scan rate
against the set one, checksum and packet-loss counts. Scan and ranging
frequency and interference filtering are set from its panels. Without a lidar
it runs a virtual one; sessions can be recorded and replayed.
.
The headless commands, the udev rule and the serve unit are in ydscope-cli,
which this package depends on.")
# The same version of ydscope-cli (the udev rule, the completion's commands, the recordings both
# read). Mesa's drivers and a font are opened at run time, so dpkg-shlibdeps cannot see them; the
# app draws with ImGui's own font when no system font is there.
set(CPACK_DEBIAN_APP_PACKAGE_DEPENDS "ydscope-cli (= ${CPACK_PACKAGE_VERSION}), libgl1-mesa-dri")
set(CPACK_DEBIAN_APP_PACKAGE_RECOMMENDS "fonts-dejavu-core")
include(CPack)
