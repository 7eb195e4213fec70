/* Loses one heap block on purpose. The sanitizer job runs it with its own
 * LeakSanitizer options (scripts/sanitize.sh) and expects a leak report, so
 * an option that blinds the leak check fails the job instead of passing it. */
#include <stdlib.h>
#include <string.h>

static void* volatile lost; /* volatile: the allocation cannot be optimised away */

int main(void) {
  lost = malloc(48);
  memset(lost, 1, 48);
  lost = NULL;
  return 0;
}
