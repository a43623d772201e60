# rbs_forbid_ros_headers(<target>)
#
# The core must stay ROS-free, but on Debian every ROS header lives in
# /usr/include, next to libc's: include paths alone cannot keep them out.
# This puts, in front of the target's include path, a directory holding a
# stub for every installed ROS header (every header under
# <prefix>/include/<pkg>/ for each <prefix>/share/<pkg>/package.xml, plus
# <prefix>/include/ros/). Each stub is an #error, so including any ROS header
# from the target fails to compile with a message that says why.
function(rbs_forbid_ros_headers target)
  set(stub_root "${CMAKE_CURRENT_BINARY_DIR}/ros_free_includes/${target}")
  set(prefixes /usr ${CMAKE_PREFIX_PATH})
  list(REMOVE_DUPLICATES prefixes)
  set(count 0)
  foreach(prefix IN LISTS prefixes)
    file(GLOB manifests "${prefix}/share/*/package.xml")
    set(dirs ros)
    foreach(manifest IN LISTS manifests)
      get_filename_component(pkg_dir "${manifest}" DIRECTORY)
      get_filename_component(pkg "${pkg_dir}" NAME)
      list(APPEND dirs "${pkg}")
    endforeach()
    list(REMOVE_DUPLICATES dirs)
    foreach(dir IN LISTS dirs)
      if(NOT IS_DIRECTORY "${prefix}/include/${dir}")
        continue()
      endif()
      file(GLOB_RECURSE headers RELATIVE "${prefix}/include" "${prefix}/include/${dir}/*")
      foreach(header IN LISTS headers)
        set(stub "${stub_root}/${header}")
        if(NOT EXISTS "${stub}")
          file(WRITE "${stub}"
            "#error \"${target} is ROS-free: <${header}> may not be included here. "
            "ROS code belongs in the ROS adapter layer (see ARCHITECTURE.md).\"\n")
        endif()
        math(EXPR count "${count} + 1")
      endforeach()
    endforeach()
  endforeach()
  target_include_directories(${target} BEFORE PRIVATE "${stub_root}")
  message(STATUS "${target}: ${count} ROS headers made to fail (ros_free_includes)")
endfunction()
