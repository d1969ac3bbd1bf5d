/* Compiles prism.h as C99 with -pedantic -Werror: the public header must be C. */
#include "prism.h"

int prism_header_is_c(void) { return (int)sizeof(PrismRenderOptions); }
