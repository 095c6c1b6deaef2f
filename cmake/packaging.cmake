# Debian packages with CPack's DEB generator: mrd-controller (the firmware, /etc/mrd/mrd.toml as a
# conffile, the systemd unit, the maintainer scripts that create the service user) and mrd-tools.
# Build them from a tree configured for the system layout, prefix /usr (presets deb and arm64), so
# the unit's paths are the installed ones. Dependencies come from dpkg-shlibdeps. docs/DEPLOY.md.
set(MRD_PACKAGE_CONTACT "mrd maintainers <maintainers@users.noreply.h-seed-a0a00b53.example>"
    CACHE STRING "Maintainer field of the Debian packages")
include(GNUInstallDirs)
set(mrd_deb_dir ${PROJECT_SOURCE_DIR}/packaging/deb)
set(mrd_deb_release 1)

# The Debian changelog's newest entry must be the version being packaged.
file(STRINGS ${mrd_deb_dir}/changelog mrd_changelog_head LIMIT_COUNT 1)
if(NOT mrd_changelog_head MATCHES "^mrd \\(${PROJECT_VERSION}-${mrd_deb_release}\\) ")
  message(FATAL_ERROR "packaging/deb/changelog starts with '${mrd_changelog_head}', "
                      "expected version ${PROJECT_VERSION}-${mrd_deb_release}")
endif()
if(NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  message(STATUS "Packages (cpack) expect CMAKE_INSTALL_PREFIX=/usr; this tree has ${CMAKE_INSTALL_PREFIX}")
endif()

# Each package carries its copyright file and compressed changelog, as Debian policy asks.
set(mrd_changelog_gz ${CMAKE_CURRENT_BINARY_DIR}/packaging/changelog.Debian.gz)
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/packaging)
execute_process(COMMAND gzip -9nc ${mrd_deb_dir}/changelog OUTPUT_FILE ${mrd_changelog_gz}
                COMMAND_ERROR_IS_FATAL ANY)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${mrd_deb_dir}/changelog)
set(mrd_components controller tools)
set(mrd_packages mrd-controller mrd-tools)
foreach(component package IN ZIP_LISTS mrd_components mrd_packages)
  install(FILES ${mrd_deb_dir}/copyright ${mrd_changelog_gz}
          DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/${package} COMPONENT ${component})
  # The lintian tags that cannot be fixed, each with its reason (docs/DEPLOY.md, "Lintian").
  install(FILES ${mrd_deb_dir}/${package}.lintian-overrides DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/lintian/overrides
          RENAME ${package} COMPONENT ${component})
endforeach()
# The documentation (README.md, docs/ with its figures) goes with the tools, registered with
# doc-base; the controller's own (FIRMWARE.md, DEPLOY.md, ...) is installed by firmware/.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/mrd-tools
        COMPONENT tools)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/mrd-tools/docs
        COMPONENT tools)
configure_file(${mrd_deb_dir}/mrd-tools.doc-base.in ${CMAKE_CURRENT_BINARY_DIR}/packaging/mrd-tools.doc-base @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/packaging/mrd-tools.doc-base
        DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc-base RENAME mrd-tools COMPONENT tools)
# The hardware-in-the-loop configs mrd-plant needs (its man page and docs/HIL.md run them): the
# plant and the controller config it names (relative to itself), for the position and force modes.
install(FILES ${PROJECT_SOURCE_DIR}/etc/mrd/plant.toml ${PROJECT_SOURCE_DIR}/etc/mrd/hil-modbus.toml
              ${PROJECT_SOURCE_DIR}/etc/mrd/plant-force.toml ${PROJECT_SOURCE_DIR}/etc/mrd/hil-force-modbus.toml
        DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/mrd-tools/examples COMPONENT tools)

# dpkg marks the config a conffile: an upgrade keeps local edits (and asks if both changed).
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/packaging/conffiles "${CMAKE_INSTALL_FULL_SYSCONFDIR}/mrd/mrd.toml\n")

if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64)$")
  set(mrd_deb_arch arm64)
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64)$")
  set(mrd_deb_arch amd64)
endif()
# dpkg-shlibdeps reads each binary's architecture from the ELF header and looks in that
# architecture's multiarch directories, so the arm64 packages need the :arm64 libraries installed
# (scripts/setup-cross-arm64.sh) and nothing else.

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME mrd)
set(CPACK_PACKAGE_VENDOR "the mrd authors")
set(CPACK_PACKAGE_CONTACT ${MRD_PACKAGE_CONTACT})
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
# Each package's description starts with its own synopsis line. CPack would put the project's
# summary above it unless the summary is CPack's default, so it is set to that.
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${CMAKE_PROJECT_NAME} built using CMake")
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/packages)
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_SET_DESTDIR ON)  # the config and the unit install to absolute paths
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL ${mrd_components})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE ${mrd_deb_release})
if(mrd_deb_arch)
  set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${mrd_deb_arch})
endif()
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)
# A -dbgsym package (.ddeb) beside each, with the debug information detached by build id, where
# the tree is compiled with -g: the arm64 preset, the box's build (the release tree is not, for its
# compile time). CPack then strips the programs itself; CPACK_STRIP_FILES would strip them before
# the debug information is taken out, so it is set only without -g.
if(CMAKE_CXX_FLAGS MATCHES "(^| )-g[0-9]?( |$)")
  set(CPACK_DEBIAN_DEBUGINFO_PACKAGE ON)
  # The target's binutils: the host's objcopy cannot read an arm64 ELF file.
  set(CPACK_OBJCOPY_EXECUTABLE ${CMAKE_OBJCOPY})
  set(CPACK_READELF_EXECUTABLE ${CMAKE_READELF})
else()
  set(CPACK_STRIP_FILES ON)
endif()

set(CPACK_DEBIAN_CONTROLLER_PACKAGE_NAME mrd-controller)
set(CPACK_DEBIAN_CONTROLLER_PACKAGE_DEPENDS adduser)  # postinst; dpkg-shlibdeps adds the libraries
set(CPACK_DEBIAN_CONTROLLER_PACKAGE_CONTROL_EXTRA
    ${mrd_deb_dir}/postinst ${mrd_deb_dir}/prerm ${mrd_deb_dir}/postrm
    ${CMAKE_CURRENT_BINARY_DIR}/packaging/conffiles)
set(CPACK_COMPONENT_CONTROLLER_DESCRIPTION
    "real-time controller for a magnetorheological damper
mrd-controller runs the fixed-rate control loop of an MR damper: a
Jiles-Atherton hysteresis and Bingham force observer, hysteresis
compensation of the coil current and a safety supervisor, over Modbus,
SocketCAN and GPIO. The package installs the default config
/etc/mrd/mrd.toml, the systemd unit mrd-controller.service and the
unprivileged user mrd the service runs as.")

set(CPACK_DEBIAN_TOOLS_PACKAGE_NAME mrd-tools)
set(CPACK_DEBIAN_TOOLS_PACKAGE_RECOMMENDS gnuplot-nox)  # the tools' --plot options
set(CPACK_COMPONENT_TOOLS_DESCRIPTION
    "host tools for the mrd magnetorheological damper controller
Programs that check and tune the controller away from the box, each
with its manual page: mrd-table4-run (the paper's Table 4 test on the
simulated damper), mrd-ja-scan (where a Jiles-Atherton parameter set is
physical), mrd-identify (Jiles-Atherton parameters from measured B-H
loops), mrd-replay (recorded runs through the controller's observer and
control law), mrd-residual (the damper model fitted to recorded runs,
the residual traced to missing effects), mrd-simulate-run (runs from
the simulated damper), mrd-force-run (force-control strategies compared
on the simulated damper), mrd-plant (the simulated rig on the controller's
buses) and mrd-hil-report (a hardware-in-the-loop run in one page).
The project's documentation is in /usr/share/doc/mrd-tools.")

include(CPack)
