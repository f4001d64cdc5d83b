/*
 * copcfg.h - defaults-only configuration.
 *
 * For applications and tests that have no copcfg.h of their own: it sets
 * nothing, so every switch takes the value documented in copdef.h. An
 * application replaces this file with its own copcfg.h (the folder is
 * selected with COP_CONFIG_DIR, for the C compiler and the library build
 * alike).
 */
#ifndef COPCFG_H
#define COPCFG_H

#endif
