/* LD_PRELOAD'ed by scripts/sanitize.sh: dlclose does nothing, so the Vulkan
 * driver and layers that the loader unloads at vkDestroyInstance stay mapped
 * until LeakSanitizer runs at exit. LSan can then name the library of each
 * allocation frame, and the suppressions (lsan.supp) match by library name;
 * without it their frames show as "<unknown module>" and match nothing. */
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
