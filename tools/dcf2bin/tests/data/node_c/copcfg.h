/*
 * copcfg.h of the node the dcf2bin tests check containers against
 * (`dcf2bin --check tests/data/node_c`): the library's defaults, with the
 * dynamic OD and PDO bit mapping (the dynamic OD manual L-1087d, chapter 4)
 * as the tests' build of the library has them.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define OBD_USE_DYNAMIC_OD            TRUE
#define OBD_USER_OD                   TRUE
#define OBD_USE_VARIABLE_SUBINDEX_TAB TRUE
#define OBD_DYNAMIC_POOL_SIZE         2048
#define PDO_USE_BIT_MAPPING           TRUE

#endif
