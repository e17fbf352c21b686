// placeholder translation unit so an all-header core is still a library
