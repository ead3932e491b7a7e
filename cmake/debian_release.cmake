# The Debian release this is built on, as package names give it: its number (debian12), or the
# codename of testing and unstable (debian-sid). Sets TSK_DEBIAN_RELEASE.
file(STRINGS /etc/os-release TSK_OS_ID REGEX "^ID=")
file(STRINGS /etc/os-release TSK_OS_VERSION REGEX "^VERSION_ID=")
file(STRINGS /etc/os-release TSK_OS_CODENAME REGEX "^VERSION_CODENAME=")
string(REGEX REPLACE "^[A-Z_]+=\"?([^\"]*)\"?$" "\\1" TSK_OS_ID "${TSK_OS_ID}")
string(REGEX REPLACE "^[A-Z_]+=\"?([^\"]*)\"?$" "\\1" TSK_OS_VERSION "${TSK_OS_VERSION}")
string(REGEX REPLACE "^[A-Z_]+=\"?([^\"]*)\"?$" "\\1" TSK_OS_CODENAME "${TSK_OS_CODENAME}")
if(TSK_OS_VERSION)
  set(TSK_DEBIAN_RELEASE "${TSK_OS_ID}${TSK_OS_VERSION}")
else()
  set(TSK_DEBIAN_RELEASE "${TSK_OS_ID}-${TSK_OS_CODENAME}")
endif()
