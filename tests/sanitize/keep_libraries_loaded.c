/* Linked into every executable of the sanitizer build only (tools/test-sanitize.sh). LeakSanitizer looks for
 * leaks at exit, after the Vulkan loader has unloaded lavapipe, LLVM and the validation layer with dlclose; their
 * allocations then show as "<unknown module>", which lsan.supp cannot match and nobody can read. Keeping every
 * library loaded lets each leak be named. The executable's definition is the one every library's call binds to. */
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
