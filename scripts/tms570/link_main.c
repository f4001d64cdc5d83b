/*
 * Link check for the TMS570 (Cortex-R4F, big-endian) build of libcop.a:
 * a minimal application that provides exactly the symbols the library is
 * documented to need from the application (Cdrv* driver, Tgt* target,
 * App* callbacks through objdef.h) plus the C library's mem* functions,
 * and calls the main API so that the linker pulls the whole stack in.
 * Built with -nostdlib: any other undefined symbol fails the link.
 *
 * It also calls the safety API an SRDO application uses (send, GFC,
 * configuration check, CRC, status byte), so that the image holds every
 * SRDO/GFC/CRC function a safety node links: scripts/bench.sh measures
 * the code size of those modules in this image.
 */
#include <stddef.h>

typedef unsigned char BYTE;
typedef unsigned short WORD;
typedef unsigned long DWORD;

/* --- C library functions the compiler may call ------------------------ */
void *memcpy(void *d, const void *s, size_t n)
{
    unsigned char *dp = d;
    const unsigned char *sp = s;
    while (n--) *dp++ = *sp++;
    return d;
}
void *memmove(void *d, const void *s, size_t n)
{
    unsigned char *dp = d;
    const unsigned char *sp = s;
    if (dp < sp) { while (n--) *dp++ = *sp++; }
    else { dp += n; sp += n; while (n--) *--dp = *--sp; }
    return d;
}
void *memset(void *d, int c, size_t n)
{
    unsigned char *dp = d;
    while (n--) *dp++ = (unsigned char)c;
    return d;
}
int memcmp(const void *a, const void *b, size_t n)
{
    const unsigned char *x = a, *y = b;
    for (; n; n--, x++, y++) if (*x != *y) return *x - *y;
    return 0;
}
void __aeabi_memcpy(void *d, const void *s, size_t n) { memcpy(d, s, n); }
void __aeabi_memcpy4(void *d, const void *s, size_t n) { memcpy(d, s, n); }
void __aeabi_memcpy8(void *d, const void *s, size_t n) { memcpy(d, s, n); }
void __aeabi_memmove(void *d, const void *s, size_t n) { memmove(d, s, n); }
void __aeabi_memmove4(void *d, const void *s, size_t n) { memmove(d, s, n); }
void __aeabi_memmove8(void *d, const void *s, size_t n) { memmove(d, s, n); }
void __aeabi_memset(void *d, size_t n, int c) { memset(d, c, n); }
void __aeabi_memset4(void *d, size_t n, int c) { memset(d, c, n); }
void __aeabi_memset8(void *d, size_t n, int c) { memset(d, c, n); }
void __aeabi_memclr(void *d, size_t n) { memset(d, 0, n); }
void __aeabi_memclr4(void *d, size_t n) { memset(d, 0, n); }
void __aeabi_memclr8(void *d, size_t n) { memset(d, 0, n); }

/* --- driver and target (SYS TEC contract) ----------------------------- */
typedef struct { WORD id; BYTE type; BYTE size; BYTE ch; BYTE data[8]; } msg_t;
static msg_t rx;
unsigned CdrvInit(void *p) { (void)p; return 0; }
unsigned CdrvDeleteInstance(void) { return 0; }
unsigned CdrvWriteMsg(msg_t *m) { (void)m; return 0; }
unsigned CdrvReadMsg(msg_t **pp) { *pp = &rx; return 0x10; }
unsigned CdrvReleaseMsg(msg_t *m) { (void)m; return 0; }
unsigned CdrvDefineCanId(msg_t *m) { (void)m; return 0; }
unsigned CdrvUndefineCanId(msg_t *m) { (void)m; return 0; }
unsigned CdrvGetStatus(WORD *s) { *s = 0; return 0; }
unsigned CdrvResetStatus(WORD s) { (void)s; return 0; }
volatile DWORD tick;
DWORD TgtGetTickCount(void) { return tick; }

/* --- the API the application calls ------------------------------------ */
extern unsigned CcmInitCANopen(void *p, DWORD first);
extern unsigned CcmConnectToNet(void);
extern unsigned CcmProcess(void);
extern unsigned CcmShutDownCANopen(void);
extern unsigned CcmReadObject(WORD i, BYTE s, void *d, BYTE *n);
extern unsigned CcmWriteObject(WORD i, BYTE s, const void *d, BYTE n);
extern unsigned CcmSendSrdo(WORD commu);
extern unsigned CcmSendGfc(void);
extern unsigned CcmCheckSrdoConfig(WORD *commu);
extern unsigned CcmCalcSrdoCrc(WORD commu, WORD *crc);
extern unsigned CcmGetSrdoState(BYTE *state, WORD commu);
extern unsigned CcmSetSrdoState(BYTE state, WORD commu);

volatile unsigned sink;

int main(void)
{
    BYTE buf[4];
    BYTE n = sizeof buf;
    sink = CcmInitCANopen(0, 1);
    sink += CcmConnectToNet();
    sink += CcmProcess();
    sink += CcmReadObject(0x1000, 0, buf, &n);
    sink += CcmWriteObject(0x1017, 0, buf, 2);
    {
        WORD bad = 0, crc = 0;
        BYTE st = 0;
        sink += CcmCheckSrdoConfig(&bad);
        sink += CcmCalcSrdoCrc(0x1301, &crc);
        sink += CcmSendSrdo(0x1301);
        sink += CcmSendGfc();
        sink += CcmGetSrdoState(&st, 0x1301);
        sink += CcmSetSrdoState((BYTE)(st | 0x30), 0x1301);
        sink += bad + crc;
    }
    sink += CcmShutDownCANopen();
    for (;;) {
    }
}

void _start(void) { main(); }
