# Image files for the whole sample (ImageFile.h): OpenImageIO by default, or
# Debian's stb (-DDRR_IMAGE_IO=STB) for builds that must run where
# OpenImageIO's many dependencies are not installed (e.g. a bare GPU machine).
set(DRR_IMAGE_IO "OIIO" CACHE STRING "Image file backend: OIIO or STB")
set_property(CACHE DRR_IMAGE_IO PROPERTY STRINGS OIIO STB)
if(DRR_IMAGE_IO STREQUAL "STB")
  add_library(drr_imageio STATIC ${CMAKE_CURRENT_LIST_DIR}/imageio/ImageFileStb.cpp)
  target_link_libraries(drr_imageio PRIVATE stb)
elseif(DRR_IMAGE_IO STREQUAL "OIIO")
  add_library(drr_imageio STATIC ${CMAKE_CURRENT_LIST_DIR}/imageio/ImageFileOIIO.cpp)
  target_link_libraries(drr_imageio PRIVATE OpenImageIO::OpenImageIO)
else()
  message(FATAL_ERROR "DRR_IMAGE_IO must be OIIO or STB, not '${DRR_IMAGE_IO}'")
endif()
target_include_directories(drr_imageio PUBLIC ${CMAKE_CURRENT_LIST_DIR})
