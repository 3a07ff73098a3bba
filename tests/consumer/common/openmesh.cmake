# Shared by both consumer projects: when OpenMesh is installed, tessera must provide
# tessera::openmesh, and a program using it must build.
if(TARGET OpenMeshCore)
  if(NOT TARGET tessera::openmesh)
    message(FATAL_ERROR "OpenMesh is installed but tessera did not define tessera::openmesh")
  endif()
  add_executable(consumer_openmesh ${CMAKE_CURRENT_LIST_DIR}/openmesh.cpp)
  target_link_libraries(consumer_openmesh PRIVATE tessera::openmesh)
endif()
