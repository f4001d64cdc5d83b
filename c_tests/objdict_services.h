// objdict_services.h - a slave dictionary with every object of the smaller
// CCM services (test_services_api.c): pre-defined error field 0x1003, SYNC
// 0x1005/0x1006, guard time 0x100C, life time factor 0x100D, store 0x1010,
// restore 0x1011, EMCY COB-ID 0x1014 (default 0x80000000, no producer, as
// in the AWorks dictionaries), heartbeat 0x1017, synchronous counter
// overflow value 0x1019 (default 0), error behaviour 0x1029
// (sub 1 default 0x01: no state change), SDO server, and a
// synchronous TPDO 1 (type 1) mapping 0x2070/1 (bServicesOut_g). The stack
// callbacks are attached as SYS TEC objdict.h files do. Init function
// ObdInitRamServices.

#define OBD_DEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_DEFINE_MACRO

OBD_BEGIN ()

    OBD_BEGIN_PART_GENERIC ()

        OBD_BEGIN_INDEX_ROM(0x1000, 0x01, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1000, 0x00, 0x07, 0x01, tObdUnsigned32, Device_Type, 0x00000000)
        OBD_END_INDEX(0x1000)

        OBD_BEGIN_INDEX_RAM(0x1001, 0x01, NULL)
            OBD_SUBINDEX_RAM_VAR(0x1001, 0x00, 0x05, 0x01, tObdUnsigned8, Error_Register, 0x00)
        OBD_END_INDEX(0x1001)

        OBD_BEGIN_INDEX_RAM(0x1003, 0x05, EmcpCbPreDefinedErrorField)
            OBD_SUBINDEX_RAM_VAR(0x1003, 0x00, 0x05, 0x03, tObdUnsigned8, Number_of_Errors, 0x00)
            OBD_SUBINDEX_RAM_VAR(0x1003, 0x01, 0x07, 0x01, tObdUnsigned32, Standard_Error_Field_1, 0x00000000)
            OBD_SUBINDEX_RAM_VAR(0x1003, 0x02, 0x07, 0x01, tObdUnsigned32, Standard_Error_Field_2, 0x00000000)
            OBD_SUBINDEX_RAM_VAR(0x1003, 0x03, 0x07, 0x01, tObdUnsigned32, Standard_Error_Field_3, 0x00000000)
            OBD_SUBINDEX_RAM_VAR(0x1003, 0x04, 0x07, 0x01, tObdUnsigned32, Standard_Error_Field_4, 0x00000000)
        OBD_END_INDEX(0x1003)

        OBD_BEGIN_INDEX_RAM(0x1005, 0x01, PdoCbCfgSyncId)
            OBD_SUBINDEX_RAM_VAR(0x1005, 0x00, 0x07, 0x83, tObdUnsigned32, COB_ID_SYNC, 0x00000080)
        OBD_END_INDEX(0x1005)

        OBD_BEGIN_INDEX_RAM(0x1006, 0x01, PdoCbCfgSyncCycle)
            OBD_SUBINDEX_RAM_VAR(0x1006, 0x00, 0x07, 0x83, tObdUnsigned32, Communication_Cycle_Period, 0x00000000)
        OBD_END_INDEX(0x1006)

        OBD_BEGIN_INDEX_RAM(0x100C, 0x01, NmtsCbConfigLifeGuarding)
            OBD_SUBINDEX_RAM_VAR(0x100C, 0x00, 0x06, 0x83, tObdUnsigned16, Guard_Time, 0x0000)
        OBD_END_INDEX(0x100C)

        OBD_BEGIN_INDEX_RAM(0x100D, 0x01, NmtsCbConfigLifeGuarding)
            OBD_SUBINDEX_RAM_VAR(0x100D, 0x00, 0x05, 0x83, tObdUnsigned8, Life_Time_Factor, 0x00)
        OBD_END_INDEX(0x100D)

        OBD_BEGIN_INDEX_RAM(0x1010, 0x04, CcmCbStore)
            OBD_SUBINDEX_ROM_VAR(0x1010, 0x00, 0x05, 0x01, tObdUnsigned8, Largest_Subindex, 0x03)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x01, 0x07, 0x03, tObdUnsigned32, Save_All, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x02, 0x07, 0x03, tObdUnsigned32, Save_Communication, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x03, 0x07, 0x03, tObdUnsigned32, Save_Application, 0x00000001)
        OBD_END_INDEX(0x1010)

        OBD_BEGIN_INDEX_RAM(0x1011, 0x04, CcmCbRestore)
            OBD_SUBINDEX_ROM_VAR(0x1011, 0x00, 0x05, 0x01, tObdUnsigned8, Largest_Subindex, 0x03)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x01, 0x07, 0x03, tObdUnsigned32, Restore_All, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x02, 0x07, 0x03, tObdUnsigned32, Restore_Communication, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x03, 0x07, 0x03, tObdUnsigned32, Restore_Application, 0x00000001)
        OBD_END_INDEX(0x1011)

        OBD_BEGIN_INDEX_RAM(0x1014, 0x01, EmcpCbConfigEmergencyId)
            OBD_SUBINDEX_RAM_VAR(0x1014, 0x00, 0x07, 0x83, tObdUnsigned32, COB_ID_EMCY, 0x80000000)
        OBD_END_INDEX(0x1014)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_BEGIN_INDEX_RAM(0x1019, 0x01, NULL)
            OBD_SUBINDEX_RAM_VAR(0x1019, 0x00, 0x05, 0x03, tObdUnsigned8, Synchronous_Counter_Overflow_Value, 0x00)
        OBD_END_INDEX(0x1019)

        OBD_BEGIN_INDEX_RAM(0x1029, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1029, 0x00, 0x05, 0x01, tObdUnsigned8, Number_of_Error_Classes, 0x01)
            OBD_SUBINDEX_RAM_VAR(0x1029, 0x01, 0x05, 0x03, tObdUnsigned8, Communication_Error, 0x01)
        OBD_END_INDEX(0x1029)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        OBD_CREATE_TXPDO_COMMU(0x1800, 0, 0x180, 0x01, 0, 0)
        OBD_CREATE_TXPDO_MAPP(0x1A00, 0, 1, 0x20700108, 0, 0, 0, 0, 0, 0, 0)

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2070, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2070, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_EXTVAR(0x2070, 0x01, 0x05, 0x0B, tObdUnsigned8, bServicesOut_g, 0x00)
        OBD_END_INDEX(0x2070)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
