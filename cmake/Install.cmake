# cmake --install: to be written (issue 7, item 6).
