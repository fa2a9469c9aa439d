# relief_target_defaults(<target>): warnings (errors under RELIEF_STRICT) and sanitizers for
# Relief's own targets only, so third-party headers never break the build.
if(RELIEF_SANITIZE)
  # Sanitizers apply to every target of ours, including the executables that link them.
  set(RELIEF_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=undefined
                             -fno-omit-frame-pointer)
  add_compile_options(${RELIEF_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined)
endif()

function(relief_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wnon-virtual-dtor
                                           -Woverloaded-virtual)
  if(RELIEF_STRICT)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  target_compile_definitions(${target} PRIVATE QT_NO_KEYWORDS
                                               GLM_FORCE_CXX17)
endfunction()
