/*
 * obdmacro.h - the objdict.h macro language.
 *
 * No include guard, on purpose. An application's objdict.h starts with
 *
 *     #define OBD_DEFINE_MACRO
 *     #include "obdmacro.h"
 *     #undef OBD_DEFINE_MACRO
 *
 * and ends with the same three lines for OBD_UNDEFINE_MACRO. objdef.h
 * includes objdict.h once per pass with exactly one pass switch defined;
 * each time, this file defines the whole macro family for that pass, and at
 * the end of objdict.h it removes it again. With no pass switch defined
 * every macro expands to nothing, so objdict.h may be included anywhere.
 *
 * Each macro below is written once, as the list of what it contributes to
 * each pass; COP_OBD_IN_<PASS>(...) keeps its argument in that pass and
 * drops it in all others. The passes (see objdef.h):
 *
 *   CHK   OBD_CREATE_CHECKS         an enum counting the SRDOs
 *   ROM   OBD_CREATE_ROM_DATA       constants: defaults, {default,low,high}
 *                                   triples, strings, constant subindices
 *   RAM   OBD_CREATE_RAM_DATA       variables initialised with their default,
 *                                   string buffers, tObdVarEntry slots,
 *                                   extern declarations of application
 *                                   variables, SRDO callback table, checks
 *   SUB   OBD_CREATE_SUBINDEX_TAB   one constant tObdSubEntry table per index
 *   IDX   OBD_CREATE_INDEX_TAB      the part tables of tObdEntry, each ending
 *                                   with index 0xFFFF
 *   INIT  OBD_CREATE_INIT_FUNCTION  statements inside ObdInitRam
 *
 * Parameters (as in the SYS TEC manual): ind index, sub subindex, cnt number
 * of entries, call OBD callback or NULL, typ kObdTyp* (or its number), acc
 * kObdAcc* (or its number), dtyp C type, name C identifier, val default,
 * low/high limits, size maximum string length, num running number of an
 * SDO/PDO/SRDO.
 */

#if defined(OBD_DEFINE_MACRO)

/* ---- pass selectors ------------------------------------------------------ */
#if defined(OBD_CREATE_CHECKS)
#define COP_OBD_IN_CHK(...) __VA_ARGS__
#else
#define COP_OBD_IN_CHK(...)
#endif
#if defined(OBD_CREATE_ROM_DATA)
#define COP_OBD_IN_ROM(...) __VA_ARGS__
#else
#define COP_OBD_IN_ROM(...)
#endif
#if defined(OBD_CREATE_RAM_DATA)
#define COP_OBD_IN_RAM(...) __VA_ARGS__
#else
#define COP_OBD_IN_RAM(...)
#endif
#if defined(OBD_CREATE_SUBINDEX_TAB)
#define COP_OBD_IN_SUB(...) __VA_ARGS__
#else
#define COP_OBD_IN_SUB(...)
#endif
#if defined(OBD_CREATE_INDEX_TAB)
#define COP_OBD_IN_IDX(...) __VA_ARGS__
#else
#define COP_OBD_IN_IDX(...)
#endif
#if defined(OBD_CREATE_INIT_FUNCTION)
#define COP_OBD_IN_INIT(...) __VA_ARGS__
#else
#define COP_OBD_IN_INIT(...)
#endif

/* ---- frame ------------------------------------------------------------------ */
#define OBD_BEGIN()
#define OBD_END()

#define OBD_BEGIN_PART_GENERIC() \
    COP_OBD_IN_IDX(static CONST tObdEntry ROM aObdTabGeneric_g[] = {) \
    COP_OBD_IN_INIT(COP_OBD_INIT_PARAM->m_pGenericPart = &aObdTabGeneric_g[0];)
#define OBD_BEGIN_PART_MANUFACTURER() \
    COP_OBD_IN_IDX(static CONST tObdEntry ROM aObdTabManufacturer_g[] = {) \
    COP_OBD_IN_INIT(COP_OBD_INIT_PARAM->m_pManufacturerPart = &aObdTabManufacturer_g[0];)
#define OBD_BEGIN_PART_DEVICE() \
    COP_OBD_IN_IDX(static CONST tObdEntry ROM aObdTabDevice_g[] = {) \
    COP_OBD_IN_INIT(COP_OBD_INIT_PARAM->m_pDevicePart = &aObdTabDevice_g[0];)
#define OBD_END_PART() \
    COP_OBD_IN_IDX({ (WORD) OBD_TABLE_INDEX_END, NULL, 0, NULL } };)

/* ---- plain indices ------------------------------------------------------------- */
#define OBD_BEGIN_INDEX_ROM(ind, cnt, call) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = {) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, COP_OBD_COUNT(ind), call))
#define OBD_BEGIN_INDEX_RAM(ind, cnt, call) \
    OBD_BEGIN_INDEX_ROM(ind, cnt, call)
#define OBD_END_INDEX(ind) \
    COP_OBD_IN_SUB(};)

/* ---- arrays: sub 0 = cnt (constant), sub 1..cnt = the elements ------------------ */
#define OBD_ROM_INDEX_RAM_ARRAY(ind, cnt, call, typ, acc, dtyp, name, def) \
    COP_OBD_IN_ROM(static CONST BYTE ROM COP_OBD_DEF(ind, 0x00) = (BYTE) (cnt); \
                   static CONST dtyp ROM COP_OBD_DEF(ind, 0x01) = (dtyp) (def);) \
    COP_OBD_IN_RAM(static dtyp MEM COP_OBD_ACUR(ind)[cnt];) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_ARRAY_COUNT_ENTRY(ind) \
        COP_OBD_SUBENTRY(0x01, typ, (acc) | kObdAccArray, kObdKindRam, sizeof(dtyp), \
                         &COP_OBD_DEF(ind, 0x01), &COP_OBD_ACUR(ind)[0]) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, 2, call))

#define OBD_ROM_INDEX_RAM_EXTARRAY(ind, cnt, call, typ, acc, dtyp, name, def) \
    COP_OBD_IN_ROM(static CONST BYTE ROM COP_OBD_DEF(ind, 0x00) = (BYTE) (cnt); \
                   static CONST dtyp ROM COP_OBD_DEF(ind, 0x01) = (dtyp) (def);) \
    COP_OBD_IN_RAM(extern dtyp MEM name[cnt];) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_ARRAY_COUNT_ENTRY(ind) \
        COP_OBD_SUBENTRY(0x01, typ, (acc) | kObdAccArray, kObdKindRam, sizeof(dtyp), \
                         &COP_OBD_DEF(ind, 0x01), &name[0]) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, 2, call))

#define OBD_ROM_INDEX_RAM_VARARRAY(ind, cnt, call, typ, acc, dtyp, name, def) \
    COP_OBD_IN_ROM(static CONST BYTE ROM COP_OBD_DEF(ind, 0x00) = (BYTE) (cnt); \
                   static CONST dtyp ROM COP_OBD_DEF(ind, 0x01) = (dtyp) (def);) \
    COP_OBD_IN_RAM(static tObdVarEntry MEM COP_OBD_AVAR(ind)[cnt];) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_ARRAY_COUNT_ENTRY(ind) \
        COP_OBD_SUBENTRY(0x01, typ, (acc) | kObdAccArray | kObdAccVar, kObdKindVarEntry, sizeof(dtyp), \
                         &COP_OBD_DEF(ind, 0x01), &COP_OBD_AVAR(ind)[0]) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, 2, call))

/* ---- subindices ------------------------------------------------------------------ */

/* Constant: the write bit is removed and the const bit set. */
#define OBD_SUBINDEX_ROM_VAR(ind, sub, typ, acc, dtyp, name, val) \
    COP_OBD_IN_ROM(static CONST dtyp ROM COP_OBD_DEF(ind, sub) = (dtyp) (val);) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, COP_OBD_ROM_ACC(acc), kObdKindRom, sizeof(dtyp), \
                                    &COP_OBD_DEF(ind, sub), NULL))

/* Variable in the dictionary's RAM, initialised with val. */
#define OBD_SUBINDEX_RAM_VAR(ind, sub, typ, acc, dtyp, name, val) \
    COP_OBD_IN_ROM(static CONST dtyp ROM COP_OBD_DEF(ind, sub) = (dtyp) (val);) \
    COP_OBD_IN_RAM(static dtyp MEM COP_OBD_CUR(ind, sub) = (dtyp) (val);) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, acc, kObdKindRam, sizeof(dtyp), \
                                    &COP_OBD_DEF(ind, sub), &COP_OBD_CUR(ind, sub)))

/* Variable with value range: writes outside [low, high] are refused. */
#define OBD_SUBINDEX_RAM_VAR_RG(ind, sub, typ, acc, dtyp, name, val, low, high) \
    COP_OBD_IN_ROM(static CONST dtyp ROM COP_OBD_DEF(ind, sub)[3] = { (dtyp) (val), (dtyp) (low), (dtyp) (high) };) \
    COP_OBD_IN_RAM(static dtyp MEM COP_OBD_CUR(ind, sub) = (dtyp) (val);) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, (acc) | kObdAccRange, kObdKindRam, sizeof(dtyp), \
                                    &COP_OBD_DEF(ind, sub)[0], &COP_OBD_CUR(ind, sub)))

/* The value lives in the application's variable `name` (dtyp name;). */
#define OBD_SUBINDEX_RAM_EXTVAR(ind, sub, typ, acc, dtyp, name, val) \
    COP_OBD_IN_ROM(static CONST dtyp ROM COP_OBD_DEF(ind, sub) = (dtyp) (val);) \
    COP_OBD_IN_RAM(extern dtyp MEM name;) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, acc, kObdKindRam, sizeof(dtyp), \
                                    &COP_OBD_DEF(ind, sub), &name))

#define OBD_SUBINDEX_RAM_EXTVAR_RG(ind, sub, typ, acc, dtyp, name, val, low, high) \
    COP_OBD_IN_ROM(static CONST dtyp ROM COP_OBD_DEF(ind, sub)[3] = { (dtyp) (val), (dtyp) (low), (dtyp) (high) };) \
    COP_OBD_IN_RAM(extern dtyp MEM name;) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, (acc) | kObdAccRange, kObdKindRam, sizeof(dtyp), \
                                    &COP_OBD_DEF(ind, sub)[0], &name))

/* Constant visible string. */
#define OBD_SUBINDEX_ROM_VSTRING(ind, sub, acc, name, val) \
    COP_OBD_IN_ROM(static CONST char ROM COP_OBD_DEF(ind, sub)[] = val;) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, kObdTypVString, COP_OBD_ROM_ACC(acc), kObdKindRomVString, \
                                    sizeof(COP_OBD_DEF(ind, sub)) - 1, &COP_OBD_DEF(ind, sub)[0], NULL))

/* Visible string in RAM: up to `size` characters plus the terminating NUL. */
#define OBD_SUBINDEX_RAM_VSTRING(ind, sub, acc, name, size, val) \
    COP_OBD_IN_ROM(static CONST char ROM COP_OBD_DEF(ind, sub)[] = val;) \
    COP_OBD_IN_RAM(COP_OBD_CHECK(sizeof(val) <= (size) + 1, default_string_longer_than_size_##ind##_##sub) \
                   static char MEM COP_OBD_CUR(ind, sub)[(size) + 1] = val;) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, kObdTypVString, acc, kObdKindRamVString, (size), \
                                    &COP_OBD_DEF(ind, sub)[0], &COP_OBD_CUR(ind, sub)[0]))

/* Variables without default (reset leaves them unchanged). */
#define OBD_SUBINDEX_RAM_VAR_NOINIT(ind, sub, typ, acc, dtyp, name) \
    COP_OBD_IN_RAM(static dtyp MEM COP_OBD_CUR(ind, sub);) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, acc, kObdKindRam, sizeof(dtyp), NULL, &COP_OBD_CUR(ind, sub)))

#define OBD_SUBINDEX_RAM_EXTVAR_NOINIT(ind, sub, typ, acc, dtyp, name) \
    COP_OBD_IN_RAM(extern dtyp MEM name;) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, acc, kObdKindRam, sizeof(dtyp), NULL, &name))

/* Domain: the application attaches data and size with CcmDefineVarTab. */
#define OBD_SUBINDEX_RAM_DOMAIN(ind, sub, acc, name) \
    COP_OBD_IN_RAM(static tObdVarEntry MEM COP_OBD_VAR(ind, sub);) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, kObdTypDomain, (acc) | kObdAccVar, kObdKindVarEntry, 0, \
                                    NULL, &COP_OBD_VAR(ind, sub)))

/* User-defined: a variable of type dtyp attached with CcmDefineVarTab. */
#define OBD_SUBINDEX_RAM_USERDEF(ind, sub, typ, acc, dtyp, name, val) \
    COP_OBD_IN_ROM(static CONST dtyp ROM COP_OBD_DEF(ind, sub) = (dtyp) (val);) \
    COP_OBD_IN_RAM(static tObdVarEntry MEM COP_OBD_VAR(ind, sub);) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, (acc) | kObdAccVar, kObdKindVarEntry, sizeof(dtyp), \
                                    &COP_OBD_DEF(ind, sub), &COP_OBD_VAR(ind, sub)))

#define OBD_SUBINDEX_RAM_USERDEF_RG(ind, sub, typ, acc, dtyp, name, val, low, high) \
    COP_OBD_IN_ROM(static CONST dtyp ROM COP_OBD_DEF(ind, sub)[3] = { (dtyp) (val), (dtyp) (low), (dtyp) (high) };) \
    COP_OBD_IN_RAM(static tObdVarEntry MEM COP_OBD_VAR(ind, sub);) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, (acc) | kObdAccVar | kObdAccRange, kObdKindVarEntry, sizeof(dtyp), \
                                    &COP_OBD_DEF(ind, sub)[0], &COP_OBD_VAR(ind, sub)))

#define OBD_SUBINDEX_RAM_USERDEF_NOINIT(ind, sub, typ, acc, dtyp, name) \
    COP_OBD_IN_RAM(static tObdVarEntry MEM COP_OBD_VAR(ind, sub);) \
    COP_OBD_IN_SUB(COP_OBD_SUBENTRY(sub, typ, (acc) | kObdAccVar, kObdKindVarEntry, sizeof(dtyp), \
                                    NULL, &COP_OBD_VAR(ind, sub)))

/* ---- SDO -------------------------------------------------------------------------- */

/* Server parameter 0x1200+num: sub 0 = 2 for 0x1200 (which has no sub 3),
 * 3 otherwise; sub 1 COB-ID client->server, sub 2 server->client, sub 3
 * node-ID of the client. The default server's COB-IDs are read-only
 * (CiA 301); 0x600 / 0x580 there stand for "base + node-ID". */
#define OBD_CREATE_SDOS(ind, num, cobcs, cobsc, idc) \
    COP_OBD_IN_ROM(static CONST BYTE ROM COP_OBD_DEF(ind, 0x00) = (BYTE) (((ind) == 0x1200) ? 2 : 3); \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x01, cobcs) \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x02, cobsc) \
                   COP_OBD_PARAM_ROM(BYTE, ind, 0x03, idc)) \
    COP_OBD_IN_RAM(COP_OBD_CHECK((num) < SDO_MAX_SERVER_IN_OBD, SDO_server_number_##num##_not_below_SDO_MAX_SERVER_IN_OBD) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x01, cobcs) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x02, cobsc) \
                   COP_OBD_PARAM_RAM(BYTE, ind, 0x03, idc)) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_CONST_U8_ENTRY(ind, 0x00) \
        COP_OBD_PARAM_ENTRY(ind, 0x01, kObdTypUInt32, COP_OBD_SDOS_COBID_ACC(ind), DWORD) \
        COP_OBD_PARAM_ENTRY(ind, 0x02, kObdTypUInt32, COP_OBD_SDOS_COBID_ACC(ind), DWORD) \
        COP_OBD_PARAM_ENTRY(ind, 0x03, kObdTypUInt8, kObdAccSRW, BYTE) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, (((ind) == 0x1200) ? 3 : 4), SdosCbConfigServer))

/* Client parameter 0x1280+num: sub 1 COB-ID client->server, sub 2
 * server->client, sub 3 node-ID of the server. */
#define OBD_CREATE_SDOC(ind, num, cobcs, cobsc, ids) \
    COP_OBD_IN_ROM(static CONST BYTE ROM COP_OBD_DEF(ind, 0x00) = 3; \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x01, cobcs) \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x02, cobsc) \
                   COP_OBD_PARAM_ROM(BYTE, ind, 0x03, ids)) \
    COP_OBD_IN_RAM(COP_OBD_CHECK((num) < SDO_MAX_CLIENT_IN_OBD, SDO_client_number_##num##_not_below_SDO_MAX_CLIENT_IN_OBD) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x01, cobcs) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x02, cobsc) \
                   COP_OBD_PARAM_RAM(BYTE, ind, 0x03, ids)) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_CONST_U8_ENTRY(ind, 0x00) \
        COP_OBD_PARAM_ENTRY(ind, 0x01, kObdTypUInt32, kObdAccSRW, DWORD) \
        COP_OBD_PARAM_ENTRY(ind, 0x02, kObdTypUInt32, kObdAccSRW, DWORD) \
        COP_OBD_PARAM_ENTRY(ind, 0x03, kObdTypUInt8, kObdAccSRW, BYTE) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, 4, SdocCbConfigClient))

/* ---- PDO ------------------------------------------------------------------------ */

/* Communication parameter: subs 0 (= 5), 1 COB-ID, 2 transmission type,
 * 3 inhibit time, 5 event timer. */
#define COP_OBD_PDO_COMMU(ind, num, max, cob, ttyp, inh, evt) \
    COP_OBD_IN_ROM(static CONST BYTE ROM COP_OBD_DEF(ind, 0x00) = 5; \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x01, cob) \
                   COP_OBD_PARAM_ROM(BYTE, ind, 0x02, ttyp) \
                   COP_OBD_PARAM_ROM(WORD, ind, 0x03, inh) \
                   COP_OBD_PARAM_ROM(WORD, ind, 0x05, evt)) \
    COP_OBD_IN_RAM(COP_OBD_CHECK((num) < (max), PDO_number_##num##_of_##ind##_too_high) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x01, cob) \
                   COP_OBD_PARAM_RAM(BYTE, ind, 0x02, ttyp) \
                   COP_OBD_PARAM_RAM(WORD, ind, 0x03, inh) \
                   COP_OBD_PARAM_RAM(WORD, ind, 0x05, evt)) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_CONST_U8_ENTRY(ind, 0x00) \
        COP_OBD_PARAM_ENTRY(ind, 0x01, kObdTypUInt32, kObdAccSRW, DWORD) \
        COP_OBD_PARAM_ENTRY(ind, 0x02, kObdTypUInt8, kObdAccSRW, BYTE) \
        COP_OBD_PARAM_ENTRY(ind, 0x03, kObdTypUInt16, kObdAccSRW, WORD) \
        COP_OBD_PARAM_ENTRY(ind, 0x05, kObdTypUInt16, kObdAccSRW, WORD) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, 5, PdoCbConfigCommu))

/* Mapping parameter: sub 0 number of mapped objects, subs 1..8 the mapping
 * entries (constant with PDO_USE_STATIC_MAPPING); with PDO_MAX_MAPPENTRIES
 * 64 (bit mapping, PDO_GRANULARITY 64) subs 9..64 follow, default 0
 * (objdef.h: COP_OBD_PDO_BIT_ENTRIES). */
#define COP_OBD_PDO_MAPP(ind, num, max, cnt, ob1, ob2, ob3, ob4, ob5, ob6, ob7, ob8) \
    COP_OBD_IN_ROM(COP_OBD_PARAM_ROM(BYTE, ind, 0x00, cnt) \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x01, ob1) COP_OBD_PARAM_ROM(DWORD, ind, 0x02, ob2) \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x03, ob3) COP_OBD_PARAM_ROM(DWORD, ind, 0x04, ob4) \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x05, ob5) COP_OBD_PARAM_ROM(DWORD, ind, 0x06, ob6) \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x07, ob7) COP_OBD_PARAM_ROM(DWORD, ind, 0x08, ob8) \
                   COP_OBD_PDO_BITS_ONLY(static CONST DWORD ROM COP_OBD_DEF(ind, MappBits) = 0;)) \
    COP_OBD_IN_RAM(COP_OBD_CHECK((num) < (max), PDO_number_##num##_of_##ind##_too_high) \
                   PDO_STATIC_MAPPING_ONEOF(, \
                   COP_OBD_PARAM_RAM(BYTE, ind, 0x00, cnt) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x01, ob1) COP_OBD_PARAM_RAM(DWORD, ind, 0x02, ob2) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x03, ob3) COP_OBD_PARAM_RAM(DWORD, ind, 0x04, ob4) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x05, ob5) COP_OBD_PARAM_RAM(DWORD, ind, 0x06, ob6) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x07, ob7) COP_OBD_PARAM_RAM(DWORD, ind, 0x08, ob8) \
                   COP_OBD_PDO_BITS_ONLY(static DWORD MEM COP_OBD_ACUR(ind)[PDO_MAX_MAPPENTRIES - 8];))) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_PDO_MAPP_ENTRY(ind, 0x00, kObdTypUInt8, BYTE) \
        COP_OBD_PDO_MAPP_ENTRY(ind, 0x01, kObdTypUInt32, DWORD) COP_OBD_PDO_MAPP_ENTRY(ind, 0x02, kObdTypUInt32, DWORD) \
        COP_OBD_PDO_MAPP_ENTRY(ind, 0x03, kObdTypUInt32, DWORD) COP_OBD_PDO_MAPP_ENTRY(ind, 0x04, kObdTypUInt32, DWORD) \
        COP_OBD_PDO_MAPP_ENTRY(ind, 0x05, kObdTypUInt32, DWORD) COP_OBD_PDO_MAPP_ENTRY(ind, 0x06, kObdTypUInt32, DWORD) \
        COP_OBD_PDO_MAPP_ENTRY(ind, 0x07, kObdTypUInt32, DWORD) COP_OBD_PDO_MAPP_ENTRY(ind, 0x08, kObdTypUInt32, DWORD) \
        COP_OBD_PDO_BIT_ENTRIES(ind) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, PDO_MAX_MAPPENTRIES + 1, PDO_STATIC_MAPPING_ONEOF(NULL, PdoCbConfigMapp)))

#define OBD_CREATE_RXPDO_COMMU(ind, num, cob, typ, inh, evt) \
    COP_OBD_PDO_COMMU(ind, num, PDO_MAX_RXPDO_IN_OBD, cob, typ, inh, evt)
#define OBD_CREATE_TXPDO_COMMU(ind, num, cob, typ, inh, evt) \
    COP_OBD_PDO_COMMU(ind, num, PDO_MAX_TXPDO_IN_OBD, cob, typ, inh, evt)
#define OBD_CREATE_RXPDO_MAPP(ind, num, cnt, ob1, ob2, ob3, ob4, ob5, ob6, ob7, ob8) \
    COP_OBD_PDO_MAPP(ind, num, PDO_MAX_RXPDO_IN_OBD, cnt, ob1, ob2, ob3, ob4, ob5, ob6, ob7, ob8)
#define OBD_CREATE_TXPDO_MAPP(ind, num, cnt, ob1, ob2, ob3, ob4, ob5, ob6, ob7, ob8) \
    COP_OBD_PDO_MAPP(ind, num, PDO_MAX_TXPDO_IN_OBD, cnt, ob1, ob2, ob3, ob4, ob5, ob6, ob7, ob8)

/* ---- SRDO (CiA 304) ---------------------------------------------------------------- */

/* 0x1300 global fail-safe command parameter (UNSIGNED8 rw, default 0). */
#define OBD_CREATE_SRDO_GFC_PARAM() \
    COP_OBD_IN_ROM(COP_OBD_PARAM_ROM(BYTE, 0x1300, 0x00, 0)) \
    COP_OBD_IN_RAM(COP_OBD_PARAM_RAM(BYTE, 0x1300, 0x00, 0)) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(0x1300)[] = { \
        COP_OBD_PARAM_ENTRY(0x1300, 0x00, kObdTypUInt8, kObdAccRW, BYTE) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(0x1300, 1, SrdoCbConfig))

/* 0x1301+n communication parameter: 0 = 6 (const), 1 direction, 2 SCT
 * (refresh time, ms), 3 SRVT (ms), 4 transmission type 254 (const),
 * 5 COB-ID of the normal frame, 6 COB-ID of the inverted frame. */
#define OBD_CREATE_SRDO_COMMU(ind, num, dir, sct, srvt, cob1, cob2) \
    COP_OBD_IN_CHK(+ 1) \
    COP_OBD_IN_ROM(static CONST BYTE ROM COP_OBD_DEF(ind, 0x00) = 6; \
                   COP_OBD_PARAM_ROM(BYTE, ind, 0x01, dir) \
                   COP_OBD_PARAM_ROM(WORD, ind, 0x02, sct) \
                   COP_OBD_PARAM_ROM(BYTE, ind, 0x03, srvt) \
                   static CONST BYTE ROM COP_OBD_DEF(ind, 0x04) = 254; \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x05, cob1) \
                   COP_OBD_PARAM_ROM(DWORD, ind, 0x06, cob2)) \
    COP_OBD_IN_RAM(COP_OBD_CHECK((num) < SRDO_MAX_SRDO_IN_OBD, SRDO_number_##num##_not_below_SRDO_MAX_SRDO_IN_OBD) \
                   COP_OBD_PARAM_RAM(BYTE, ind, 0x01, dir) \
                   COP_OBD_PARAM_RAM(WORD, ind, 0x02, sct) \
                   COP_OBD_PARAM_RAM(BYTE, ind, 0x03, srvt) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x05, cob1) \
                   COP_OBD_PARAM_RAM(DWORD, ind, 0x06, cob2)) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_CONST_U8_ENTRY(ind, 0x00) \
        COP_OBD_PARAM_ENTRY(ind, 0x01, kObdTypUInt8, kObdAccSRW, BYTE) \
        COP_OBD_PARAM_ENTRY(ind, 0x02, kObdTypUInt16, kObdAccSRW, WORD) \
        COP_OBD_PARAM_ENTRY(ind, 0x03, kObdTypUInt8, kObdAccSRW, BYTE) \
        COP_OBD_CONST_U8_ENTRY(ind, 0x04) \
        COP_OBD_PARAM_ENTRY(ind, 0x05, kObdTypUInt32, kObdAccSRW, DWORD) \
        COP_OBD_PARAM_ENTRY(ind, 0x06, kObdTypUInt32, kObdAccSRW, DWORD) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, 7, SrdoCbConfig)) \
    COP_OBD_IN_INIT(COP_OBD_INIT_PARAM->m_pSrdoCallbacks = &COP_OBD_SRDO_CALLBACKS;)

/* 0x1381+n mapping parameter: sub 0 number of entries, then UNSIGNED32
 * mapping entries (constant with SRDO_USE_STATIC_MAPPING). */
#define OBD_BEGIN_SRDO_MAPP(ind, num, cnt) \
    COP_OBD_IN_ROM(COP_OBD_PARAM_ROM(BYTE, ind, 0x00, cnt)) \
    COP_OBD_IN_RAM(COP_OBD_CHECK((num) < SRDO_MAX_SRDO_IN_OBD, SRDO_mapping_number_##num##_not_below_SRDO_MAX_SRDO_IN_OBD) \
                   SRDO_STATIC_MAPPING_ONEOF(, COP_OBD_PARAM_RAM(BYTE, ind, 0x00, cnt))) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(ind)[] = { \
        COP_OBD_SRDO_MAPP_ENTRY(ind, 0x00, kObdTypUInt8, BYTE)) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(ind, COP_OBD_COUNT(ind), SRDO_STATIC_MAPPING_ONEOF(NULL, SrdoCbConfigMapp)))
#define OBD_SUBINDEX_SRDO_MAPP(ind, sub, num, name, val) \
    COP_OBD_IN_ROM(COP_OBD_PARAM_ROM(DWORD, ind, sub, val)) \
    COP_OBD_IN_RAM(SRDO_STATIC_MAPPING_ONEOF(, COP_OBD_PARAM_RAM(DWORD, ind, sub, val))) \
    COP_OBD_IN_SUB(COP_OBD_SRDO_MAPP_ENTRY(ind, sub, kObdTypUInt32, DWORD))
#define OBD_END_SRDO_MAPP(ind) \
    COP_OBD_IN_SUB(};)

/* 0x13FE configuration valid (UNSIGNED8 rw, default 0; 0xA5 = valid). Also
 * emits the table of the application's SRDO callbacks, which objdef.h hands
 * to the stack (so only applications with SRDO objects define them). */
#define OBD_CREATE_SRDO_CFG_VALID() \
    COP_OBD_IN_ROM(COP_OBD_PARAM_ROM(BYTE, 0x13FE, 0x00, 0)) \
    COP_OBD_IN_RAM(COP_OBD_PARAM_RAM(BYTE, 0x13FE, 0x00, 0) \
                   static CONST tSrdoAppCallbacks ROM COP_OBD_SRDO_CALLBACKS = \
                       { AppSrdoEvent, AppSrdoError, COP_OBD_APP_GFC_EVENT, COP_OBD_APP_PROGMON_EVENT };) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(0x13FE)[] = { \
        COP_OBD_PARAM_ENTRY(0x13FE, 0x00, kObdTypUInt8, kObdAccRW, BYTE) };) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(0x13FE, 1, SrdoCbConfig)) \
    COP_OBD_IN_INIT(COP_OBD_INIT_PARAM->m_pSrdoCallbacks = &COP_OBD_SRDO_CALLBACKS;)

/* 0x13FF safety configuration checksums: sub 0 = cnt (const), sub n the
 * CRC of the n-th SRDO (0x1300+n), UNSIGNED16 rw. OBD_SUBINDEX_SRDO_CRC
 * takes (sub, name) as in the manual or (sub, name, default). */
#define OBD_BEGIN_SRDO_CRC(cnt) \
    COP_OBD_IN_ROM(COP_OBD_PARAM_ROM(BYTE, 0x13FF, 0x00, cnt)) \
    COP_OBD_IN_SUB(static CONST tObdSubEntry ROM COP_OBD_SUBTAB(0x13FF)[] = { \
        COP_OBD_CONST_U8_ENTRY(0x13FF, 0x00)) \
    COP_OBD_IN_IDX(COP_OBD_INDEX(0x13FF, COP_OBD_COUNT(0x13FF), SrdoCbConfig))
#define OBD_SUBINDEX_SRDO_CRC(sub, ...) \
    COP_OBD_SRDO_CRC_(sub, __VA_ARGS__, 0, ~)
#define COP_OBD_SRDO_CRC_(sub, name, val, ...) \
    COP_OBD_IN_ROM(COP_OBD_PARAM_ROM(WORD, 0x13FF, sub, val)) \
    COP_OBD_IN_RAM(COP_OBD_PARAM_RAM(WORD, 0x13FF, sub, val)) \
    COP_OBD_IN_SUB(COP_OBD_PARAM_ENTRY(0x13FF, sub, kObdTypUInt16, kObdAccRW, WORD))
#define OBD_END_SRDO_CRC() \
    COP_OBD_IN_SUB(};)

#elif defined(OBD_UNDEFINE_MACRO)

#undef COP_OBD_IN_CHK
#undef COP_OBD_IN_ROM
#undef COP_OBD_IN_RAM
#undef COP_OBD_IN_SUB
#undef COP_OBD_IN_IDX
#undef COP_OBD_IN_INIT

#undef OBD_BEGIN
#undef OBD_END
#undef OBD_BEGIN_PART_GENERIC
#undef OBD_BEGIN_PART_MANUFACTURER
#undef OBD_BEGIN_PART_DEVICE
#undef OBD_END_PART
#undef OBD_BEGIN_INDEX_ROM
#undef OBD_BEGIN_INDEX_RAM
#undef OBD_END_INDEX
#undef OBD_ROM_INDEX_RAM_ARRAY
#undef OBD_ROM_INDEX_RAM_EXTARRAY
#undef OBD_ROM_INDEX_RAM_VARARRAY
#undef OBD_SUBINDEX_ROM_VAR
#undef OBD_SUBINDEX_RAM_VAR
#undef OBD_SUBINDEX_RAM_VAR_RG
#undef OBD_SUBINDEX_RAM_EXTVAR
#undef OBD_SUBINDEX_RAM_EXTVAR_RG
#undef OBD_SUBINDEX_ROM_VSTRING
#undef OBD_SUBINDEX_RAM_VSTRING
#undef OBD_SUBINDEX_RAM_VAR_NOINIT
#undef OBD_SUBINDEX_RAM_EXTVAR_NOINIT
#undef OBD_SUBINDEX_RAM_DOMAIN
#undef OBD_SUBINDEX_RAM_USERDEF
#undef OBD_SUBINDEX_RAM_USERDEF_RG
#undef OBD_SUBINDEX_RAM_USERDEF_NOINIT
#undef OBD_CREATE_SDOS
#undef OBD_CREATE_SDOC
#undef COP_OBD_PDO_COMMU
#undef COP_OBD_PDO_MAPP
#undef OBD_CREATE_RXPDO_COMMU
#undef OBD_CREATE_RXPDO_MAPP
#undef OBD_CREATE_TXPDO_COMMU
#undef OBD_CREATE_TXPDO_MAPP
#undef OBD_CREATE_SRDO_GFC_PARAM
#undef OBD_CREATE_SRDO_COMMU
#undef OBD_BEGIN_SRDO_MAPP
#undef OBD_SUBINDEX_SRDO_MAPP
#undef OBD_END_SRDO_MAPP
#undef OBD_CREATE_SRDO_CFG_VALID
#undef OBD_BEGIN_SRDO_CRC
#undef OBD_SUBINDEX_SRDO_CRC
#undef COP_OBD_SRDO_CRC_
#undef OBD_END_SRDO_CRC

#endif
