# The Debian package: ydscope_<version>_<arch>.deb. Its Depends are what dpkg-shlibdeps finds the
# binaries link (so they follow the build machine's libraries), plus what is loaded at run time.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ydscope)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "ydscope maintainers <ydscope@lists.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "real-time viewer and toolkit for YDLIDAR G1, G6 and TG lidars")
# The long description; CPack puts the summary above it and indents each line for the control file.
set(CPACK_PACKAGE_DESCRIPTION "ydscope shows the scan of a YDLIDAR G1, G6 or TG-series (TG15, TG30, TG50) 2D
spinning lidar live: health bits, device information, the real scan rate
against the set one, checksum and packet-loss counts. Scan and ranging
frequency and interference filtering are set from its panels. Without a lidar
it runs a virtual one; sessions can be recorded and replayed.

ydscope-cli is the headless twin: it lists ports, queries a device, prints
laps as JSON lines, records, replays and decodes. A udev rule gives the
logged-in user the lidar's USB-serial port.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # ydscope_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Mesa's drivers and a font are opened at run time, so dpkg-shlibdeps cannot see them; the app
# draws with ImGui's own font when no system font is there.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libgl1-mesa-dri")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fonts-dejavu-core")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${CMAKE_CURRENT_SOURCE_DIR}/postinst)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
include(CPack)
