/*
 * manual_app.c - the application code of the SYS TEC safety manual
 * (L-1077d, sections 2.6 and 2.9.1 - 2.9.5), written out for this library:
 * AppSrdoEvent, AppSrdoError, AppGfcEvent, AppProgMonEvent and the SRDO
 * part of AppCbNmtEvent, with the logic, the API calls and the names the
 * manual uses. Where the manual leaves a branch open ("..."), this file
 * counts it as a safety-critical error (uSafetyCritical_g) so the test can
 * see it.
 *
 * It compiles unchanged against cop.h with static SRDO mapping
 * (c_tests/cfg_manual), except for one call: see kNmtEvEnterOperational.
 */
#include "manual_app.h"

/* The two variable fields of SRDO 1 (manual 2.6). */
tSrdoVarField SrdoNormalData;
tSrdoVarField SrdoInversData;

WORD            wPMonValue_g;
BYTE            bSrdoState = kNotOperational;
tSrdoCommuParam SrdoCommuParam;
unsigned        uSafetyCritical_g;
unsigned        uOutputsOn_g;
unsigned        uOutputsOff_g;
tCopKernel      LastSrdoError_g;

/* 2.9.1: an SRDO was received (or sent) without error. */
tCopKernel PUBLIC AppSrdoEvent (WORD wSrdoCommuIndex_p)
{
    BYTE bSrdoState_l;
    tCopKernel Ret;

    Ret = CcmGetSrdoState(&bSrdoState_l, wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        uSafetyCritical_g++;
        return kCopSuccessful;
    }

    /* the library must have marked the transfer "ok" (bits 4-5 = 00) */
    if ((bSrdoState_l & 0x30) != 0x00)
    {
        uSafetyCritical_g++;
    }

    /* use the data, e.g. switch the SRDO's outputs on */
    uOutputsOn_g++;

    /* mark the SRDO "processed" (bits 4-5 = 11) */
    Ret = CcmSetSrdoState((BYTE) (bSrdoState_l | 0x30), wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        uSafetyCritical_g++;
    }

    return kCopSuccessful;
}

/* 2.9.2: an SRDO transfer failed. */
tCopKernel PUBLIC AppSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    BYTE bSrdoState_l;
    tCopKernel Ret;

    LastSrdoError_g = ErrorCode_p;
    Ret = CcmGetSrdoState(&bSrdoState_l, wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        uSafetyCritical_g++;
        return kCopSuccessful;
    }

    if ((bSrdoState_l & 0x30) == 0x10)
    {
        /* react, e.g. switch the SRDO's outputs off */
        uOutputsOff_g++;

        /* status "processed" ... */
        bSrdoState_l |= 0x30;

        /* ... and bits 6-7 from 01 to 10: the error has been handled */
        bSrdoState_l ^= 0xC0;
    }
    else
    {
        uSafetyCritical_g++;
    }

    Ret = CcmSetSrdoState(bSrdoState_l, wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        uSafetyCritical_g++;
    }

    return kCopSuccessful;
}

/* 2.9.3: a global fail-safe command arrived. */
tCopKernel PUBLIC AppGfcEvent (void)
{
    /* e.g. go to the intrinsically safe state */
    uOutputsOff_g++;

    return kCopSuccessful;
}

/* 2.9.4: one step of the library's program flow; the main loop compares
 * the sum of a cycle with the expected value. */
tCopKernel PUBLIC AppProgMonEvent (tProgMonEvent Event_p)
{
    switch (Event_p)
    {
        case kSrdoPMEvSctChecked:
            /* once per receive SRDO */
            wPMonValue_g += kPMonSctChecked;
            break;

        case kSrdoPMEvSctNotCheckedItIsTx:
            /* once per transmit SRDO */
            wPMonValue_g += kPMonSctNotCheckedItIsTx;
            break;

        case kSrdoPMEvSctNotCheckedItIsInvalid:
            /* once per SRDO that is switched off */
            wPMonValue_g += kPMonSctNotCheckedItIsInvalid;
            break;

        case kSrdoPMEvSctNotCheckedNotOperational:
            /* once for all SRDOs */
            wPMonValue_g += kPMonSctNotCheckedNotOperational;
            break;

        case kSrdoPMEvSrdoError:
            /* per faulty SRDO */
            wPMonValue_g += kPMonSrdoError;
            break;

        case kSrdoPMEvSrdoReceived:
            /* per received SRDO */
            wPMonValue_g += kPMonSrdoReceived;
            break;

        case kSrdoPMEvSrdoTransmitted:
            /* per transmitted SRDO */
            wPMonValue_g += kPMonSrdoTransmitted;
            break;

        default:
            break;
    }

    return kCopSuccessful;
}

/* 2.9.5 (and 2.6 for the variable table): the NMT callback. */
tCopKernel PUBLIC AppCbNmtEvent (tNmtEvent NmtEvent_p)
{
    /* the four mapped objects point into the two variable fields */
    static tVarParam aVarTab[4] = {
        { kVarValidSize | kVarValidData, 0x2000, 0x01, 1, &SrdoNormalData.m_abSrdoData[0], NULL, NULL },
        { kVarValidSize | kVarValidData, 0x2000, 0x02, 1, &SrdoNormalData.m_abSrdoData[1], NULL, NULL },
        { kVarValidSize | kVarValidData, 0x2100, 0x01, 1, &SrdoInversData.m_abSrdoData[0], NULL, NULL },
        { kVarValidSize | kVarValidData, 0x2100, 0x02, 1, &SrdoInversData.m_abSrdoData[1], NULL, NULL },
    };
    BYTE bDirection = 2;        /* this node receives SRDO 1 */
    BYTE bTemp;
    tCopKernel Ret = kCopSuccessful;

    switch (NmtEvent_p)
    {
        case kNmtEvEnterInitialising:
            Ret = CcmDefineVarTab(aVarTab, 4);
            break;

        case kNmtEvResetCommunication:
            /* hand the static SRDO module its variable fields */
            Ret = CcmStaticDefineSrdoVarFields(0x1301,
                &SrdoNormalData.m_abSrdoData[0],
                &SrdoInversData.m_abSrdoData[0]);
            if (Ret != kCopSuccessful)
            {
                uSafetyCritical_g++;
                break;
            }

            /* the information direction this application owns */
            Ret = CcmWriteObject(0x1301, 1, &bDirection, 1);
            if (Ret != kCopSuccessful)
            {
                uSafetyCritical_g++;
                break;
            }

            /* configuration valid (the library checks it, CRC included) */
            bTemp = 0xA5;
            Ret = CcmWriteObject(0x13FE, 0, &bTemp, 1);
            if (Ret != kCopSuccessful)
            {
                uSafetyCritical_g++;
            }
            break;

        case kNmtEvEnterPreOperational:
            /* SRDOs must not be processed any more */
            bSrdoState = kNotOperational;
            break;

        case kNmtEvEnterOperational:
            /* The manual writes CcmGetSrdoParam (0x1301, &SrdoCommuParam)
             * with two arguments. That does not compile against the
             * prototype with three (SYSTEC_API.md section 3: wSrdoCommuIndex_p,
             * pSrdoCommuParam_p, pSrdoMappParam_p). With static mapping
             * tSrdoMappParam does not exist, so the third argument is NULL. */
            Ret = CcmGetSrdoParam(0x1301, &SrdoCommuParam, NULL);
            bSrdoState = kEnterOperational;
            break;

        default:
            break;
    }

    return Ret;
}
