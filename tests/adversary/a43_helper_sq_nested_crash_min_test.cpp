// a43_helper_sq_nested_crash_min: dpgen crashes (std::bad_alloc); minimal reproducer of a24/a40 if it crashes.
