# cmake -DOUTPUT=file -DINPUTS="a;b;…" -P concatenate.cmake: writes the inputs one after
# the other into OUTPUT (the report's script from its sections' modules, src/CMakeLists.txt).
set(text "")
foreach(input IN LISTS INPUTS)
  file(READ "${input}" part)
  string(APPEND text "${part}\n")
endforeach()
file(WRITE "${OUTPUT}" "${text}")
