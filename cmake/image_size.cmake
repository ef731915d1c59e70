# cmake -DIMAGE=<file.bin> -DROOM=<bytes> -P image_size.cmake: prints the flash image's size
# against the firmware's flash room (the link already failed if it did not fit).
file(SIZE ${IMAGE} _bytes)
math(EXPR _pct "${_bytes} * 100 / ${ROOM}")
get_filename_component(_name ${IMAGE} NAME)
get_filename_component(_stem ${IMAGE} NAME_WE)
message("${_name}: flash image of ${_bytes} bytes, ${_pct}% of the ${ROOM}-byte firmware region (and ${_stem}.hex beside it)")
