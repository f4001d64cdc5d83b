-- cop_srdo.lua - CANopen Safety (CiA 304 / EN 50325-5) for Wireshark:
-- SRDO and GFC frames in SocketCAN captures, with the pair checks an SRDO
-- consumer makes.
--
-- Install: copy this one file into the personal plugins folder,
--   ~/.local/lib/wireshark/plugins/   (Linux, macOS)
--   %APPDATA%\Wireshark\plugins\       (Windows)
-- or load it for one run: tshark -X lua_script:cop_srdo.lua -r capture.pcap
--
-- What it does (on pcap link type 227, LINKTYPE_CAN_SOCKETCAN: Wireshark's
-- SocketCAN dissector decodes the frame first, then this one reads the
-- same 16-byte record, struct can_frame of Linux's linux/can.h):
--   * an identifier of SRDO n's normal frame (COB-ID 1, by default
--     0x101 + 2(n-1)) or inverted frame (COB-ID 2, by default
--     0x102 + 2(n-1)) is decoded as that SRDO's half, with its data;
--   * the pair is matched and checked as CiA 304 asks a consumer to: the
--     normal frame first, then the inverted one; the same DLC (and the DLC
--     the mapping gives, when known); every bit of the inverted data the
--     complement of the normal data; the inverted frame no later than SRVT
--     after the normal one; the normal frame of a valid pair no later than
--     SCT after the normal frame of the previous valid pair;
--   * every violation is an expert info of error severity on the frame
--     where it shows (cop_srdo.order, .dlc, .data, .srvt, .sct); the Info
--     column and the tree say "SRDO 3 pair ok" or what is wrong;
--   * identifier 0x001 with DLC 0 is the global fail-safe command (GFC).
--
-- Preferences (Edit > Preferences > Protocols > COP_SRDO, or tshark -o):
--   cop_srdo.sct_ms    the limit between pairs (SCT), ms, default 50
--   cop_srdo.srvt_ms   the limit between the two frames (SRVT), ms, default 20
--   cop_srdo.dlc       the data length each SRDO frame must have, 0 = any
--   cop_srdo.dcf       a DCF (CiA 306) whose objects 0x1301.. (sub 1
--                      direction, sub 2 SCT or refresh time, sub 3 SRVT,
--                      sub 5/6 COB-IDs) and 0x1381.. (mapping, for the
--                      DLC) configure the SRDOs it describes; SRDOs it
--                      does not describe keep the defaults above
--
-- The checks need the frames in capture order: Wireshark makes a first pass
-- in order; with tshark use -2 (two passes) to see the pair result on the
-- normal frame as well.

local proto = Proto("cop_srdo", "CANopen Safety (SRDO, GFC)")

-- The bit library differs between Lua versions of Wireshark.
local bitlib = bit32 or bit
local bxor, band = bitlib.bxor, bitlib.band

local f_kind    = ProtoField.string("cop_srdo.kind", "Kind")
local f_number  = ProtoField.uint8("cop_srdo.number", "SRDO number", base.DEC)
local f_cob     = ProtoField.uint16("cop_srdo.cob_id", "COB-ID", base.HEX)
local f_dlc     = ProtoField.uint8("cop_srdo.dlc", "DLC", base.DEC)
local f_data    = ProtoField.bytes("cop_srdo.data", "Data")
local f_partner = ProtoField.framenum("cop_srdo.partner", "Other frame of the pair")
local f_gap     = ProtoField.double("cop_srdo.srvt_gap_ms", "Time after the normal frame (ms)")
local f_cycle   = ProtoField.double("cop_srdo.cycle_ms", "Time since the previous valid pair (ms)")
local f_status  = ProtoField.string("cop_srdo.status", "Status")
local f_ok      = ProtoField.bool("cop_srdo.ok", "Pair ok")
proto.fields = { f_kind, f_number, f_cob, f_dlc, f_data, f_partner, f_gap, f_cycle, f_status, f_ok }

local e_order = ProtoExpert.new("cop_srdo.order", "SRDO frames not in order",
    expert.group.SEQUENCE, expert.severity.ERROR)
local e_dlc = ProtoExpert.new("cop_srdo.dlc", "SRDO DLC not valid",
    expert.group.MALFORMED, expert.severity.ERROR)
local e_data = ProtoExpert.new("cop_srdo.data", "SRDO inverted data not the complement",
    expert.group.MALFORMED, expert.severity.ERROR)
local e_srvt = ProtoExpert.new("cop_srdo.srvt", "SRDO SRVT exceeded",
    expert.group.SEQUENCE, expert.severity.ERROR)
local e_sct = ProtoExpert.new("cop_srdo.sct", "SRDO SCT exceeded",
    expert.group.SEQUENCE, expert.severity.ERROR)
local e_gfc = ProtoExpert.new("cop_srdo.gfc_dlc", "Identifier 0x001 with data: no GFC",
    expert.group.PROTOCOL, expert.severity.NOTE)
proto.experts = { e_order, e_dlc, e_data, e_srvt, e_sct, e_gfc }

proto.prefs.sct_ms = Pref.uint("SCT (ms)", 50, "Longest time between the normal frames of two valid pairs")
proto.prefs.srvt_ms = Pref.uint("SRVT (ms)", 20, "Longest time between the normal and the inverted frame")
proto.prefs.dlc = Pref.uint("DLC", 0, "Data length of every SRDO frame (0: any, both frames equal)")
proto.prefs.dcf = Pref.string("DCF file", "", "DCF (CiA 306) with the SRDO objects 0x1301.. and 0x1381..")

-- struct can_frame: the identifier word in network byte order with the
-- flags CAN_EFF_FLAG (bit 31), CAN_RTR_FLAG (bit 30) and CAN_ERR_FLAG
-- (bit 29), the length byte, three bytes padding / reserved, 8 data bytes.
local RECORD_LEN = 16
local FLAGS_MASK = 0xE0000000

local encap_table = DissectorTable.get("wtap_encap")
local socketcan = encap_table:get_dissector(wtap_encaps.SOCKETCAN)

local GFC_ID = 0x001
local SRDO_MAX = 64

-- ---------------------------------------------------------------------
-- Configuration: COB-ID -> { n, inverted }, per SRDO its limits.

local by_cob = {}
local srdo_cfg = {}
local config_note = nil

-- A DCF value: decimal, 0x hex, 0 octal-free, with $NODEID added.
local function dcf_number(text, node_id)
    if text == nil then return nil end
    local s = text:gsub("%s", "")
    if s == "" then return nil end
    local total = 0
    local has_node = false
    for term in s:gmatch("[^+]+") do
        if term:upper() == "$NODEID" then
            has_node = true
        else
            local v = tonumber(term)
            if v == nil then return nil end
            total = total + v
        end
    end
    if has_node then total = total + (node_id or 0) end
    return total
end

-- Reads a DCF into { ["1301sub2"] = "25", ... } (section names in upper
-- case) and the node-ID of [DeviceComissioning].
local function read_dcf(path)
    local fh = io.open(path, "r")
    if fh == nil then return nil, "cannot open " .. path end
    local values = {}
    local section = nil
    local node_id = nil
    for line in fh:lines() do
        line = line:gsub("\r$", "")
        local sec = line:match("^%s*%[([^%]]+)%]")
        if sec then
            section = sec:upper()
        elseif section and not line:match("^%s*;") then
            local key, val = line:match("^%s*([%w_]+)%s*=%s*(.-)%s*$")
            if key then
                key = key:lower()
                if section == "DEVICECOMISSIONING" and key == "nodeid" then
                    node_id = tonumber(val)
                elseif key == "parametervalue" then
                    values[section] = { value = val, param = true }
                elseif key == "defaultvalue" then
                    local old = values[section]
                    if old == nil or not old.param then
                        values[section] = { value = val, param = false }
                    end
                end
            end
        end
    end
    fh:close()
    local out = {}
    for k, v in pairs(values) do
        out[k] = dcf_number(v.value, node_id)
    end
    return out, nil
end

local function configure()
    by_cob = {}
    srdo_cfg = {}
    config_note = nil
    local sct = proto.prefs.sct_ms
    local srvt = proto.prefs.srvt_ms
    local dlc = proto.prefs.dlc
    if dlc == 0 then dlc = nil end
    for n = 1, SRDO_MAX do
        srdo_cfg[n] = { sct_ms = sct, srvt_ms = srvt, dlc = dlc, source = "preferences" }
    end
    local from_dcf = {}
    local path = proto.prefs.dcf
    if path ~= nil and path ~= "" then
        local v, err = read_dcf(path)
        if v == nil then
            config_note = "DCF not read: " .. err
        else
            for n = 1, SRDO_MAX do
                local idx = string.format("%04X", 0x1300 + n)
                local dir = v[idx .. "SUB1"]
                local cob1 = v[idx .. "SUB5"]
                local cob2 = v[idx .. "SUB6"]
                if dir ~= nil and dir ~= 0 and cob1 ~= nil and cob2 ~= nil then
                    local c = {
                        sct_ms = v[idx .. "SUB2"] or sct,
                        srvt_ms = v[idx .. "SUB3"] or srvt,
                        dlc = dlc,
                        cob1 = band(cob1, 0x7FF),
                        cob2 = band(cob2, 0x7FF),
                        source = "DCF",
                    }
                    -- The DLC is the length of the normal entries (odd
                    -- subindices) of the mapping 0x1381 + n - 1.
                    local midx = string.format("%04X", 0x1380 + n)
                    local count = v[midx .. "SUB0"]
                    if count ~= nil and count > 0 then
                        local bits = 0
                        for i = 1, count, 2 do
                            local entry = v[midx .. "SUB" .. string.format("%X", i)]
                            if entry ~= nil then bits = bits + band(entry, 0xFF) end
                        end
                        c.dlc = math.floor((bits + 7) / 8)
                    end
                    srdo_cfg[n] = c
                    from_dcf[n] = true
                end
            end
        end
    end
    for n = 1, SRDO_MAX do
        local c = srdo_cfg[n]
        if not from_dcf[n] then
            c.cob1 = 0x101 + 2 * (n - 1)
            c.cob2 = c.cob1 + 1
        end
    end
    -- SRDOs of the DCF first, so that their COB-IDs win over defaults.
    for pass = 1, 2 do
        for n = 1, SRDO_MAX do
            local c = srdo_cfg[n]
            if (pass == 1) == (from_dcf[n] == true) then
                if by_cob[c.cob1] == nil then by_cob[c.cob1] = { n = n, inverted = false } end
                if by_cob[c.cob2] == nil then by_cob[c.cob2] = { n = n, inverted = true } end
            end
        end
    end
end

-- ---------------------------------------------------------------------
-- State of the first pass, and the results kept per frame number.

local state = {}     -- per SRDO: held normal frame, last valid pair
local results = {}   -- frame number -> result table

function proto.init()
    configure()
    state = {}
    results = {}
end

local function micros(pinfo)
    return math.floor(pinfo.abs_ts * 1000000 + 0.5)
end

local function ms(us)
    return us / 1000
end

local function hex(bytes)
    local t = {}
    for i = 1, #bytes do t[i] = string.format("%02X", bytes[i]) end
    return table.concat(t, " ")
end

-- One error: expert field, text.
local function add_error(r, expert_field, text)
    r.errors[#r.errors + 1] = { expert = expert_field, text = text }
end

local function srdo_state(n)
    local s = state[n]
    if s == nil then
        s = { held = nil, last_valid = nil }
        state[n] = s
    end
    return s
end

-- The first pass over a frame of SRDO n.
local function check_frame(r, n, inverted, t_us, dlc, data, number)
    local c = srdo_cfg[n]
    local s = srdo_state(n)
    local held = s.held
    -- A held normal frame whose SRVT has passed lost its inverted frame.
    if held ~= nil and t_us - held.t_us > c.srvt_ms * 1000 and not inverted then
        add_error(r, e_order, string.format(
            "SRDO %d: inverted frame of frame %d missing (SRVT %d ms passed)", n, held.number, c.srvt_ms))
        held.result.status = string.format("SRDO %d normal frame without inverted frame", n)
        s.held = nil
        held = nil
    end
    if not inverted then
        if s.last_valid ~= nil then
            local cycle = t_us - s.last_valid.t_us
            r.cycle_ms = ms(cycle)
            if cycle > c.sct_ms * 1000 then
                add_error(r, e_sct, string.format(
                    "SRDO %d: SCT exceeded, %.1f ms since the pair of frame %d (SCT %d ms)",
                    n, ms(cycle), s.last_valid.number, c.sct_ms))
                s.last_valid = nil -- reported once per expiry
            end
        end
        if held ~= nil then
            add_error(r, e_order, string.format(
                "SRDO %d: normal frame again, inverted frame of frame %d missing", n, held.number))
            held.result.status = string.format("SRDO %d normal frame without inverted frame", n)
            s.held = nil
        end
        if c.dlc ~= nil and dlc ~= c.dlc then
            add_error(r, e_dlc, string.format("SRDO %d: DLC %d, the mapping has %d", n, dlc, c.dlc))
            return
        end
        s.held = { number = number, t_us = t_us, dlc = dlc, data = data, result = r }
        r.status = string.format("SRDO %d normal frame, waiting for the inverted frame", n)
        return
    end
    -- the inverted frame
    if held == nil then
        add_error(r, e_order, string.format("SRDO %d: inverted frame without normal frame", n))
        return
    end
    s.held = nil
    r.partner = held.number
    held.result.partner = number
    local gap = t_us - held.t_us
    r.gap_ms = ms(gap)
    local before = #r.errors
    if gap > c.srvt_ms * 1000 then
        add_error(r, e_srvt, string.format(
            "SRDO %d: SRVT exceeded, %.1f ms after frame %d (SRVT %d ms)", n, ms(gap), held.number, c.srvt_ms))
    end
    if dlc ~= held.dlc or (c.dlc ~= nil and dlc ~= c.dlc) then
        add_error(r, e_dlc, string.format("SRDO %d: DLC %d, the normal frame %d has %d",
            n, dlc, held.number, held.dlc))
    else
        for i = 1, dlc do
            local wrong = bxor(band(bxor(held.data[i], 0xFF), 0xFF), data[i])
            if wrong ~= 0 then
                add_error(r, e_data, string.format(
                    "SRDO %d: byte %d not inverted (normal %02X, inverted %02X, bits %02X wrong)",
                    n, i - 1, held.data[i], data[i], wrong))
            end
        end
    end
    if #r.errors == before then
        r.ok = true
        held.result.ok = true
        r.status = string.format("SRDO %d pair ok", n)
        held.result.status = r.status
        s.last_valid = { number = held.number, t_us = held.t_us }
    else
        held.result.status = string.format("SRDO %d pair not valid (see frame %d)", n, number)
    end
end

-- ---------------------------------------------------------------------

function proto.dissector(tvb, pinfo, tree)
    socketcan:call(tvb, pinfo, tree)
    if tvb:len() ~= RECORD_LEN then return end -- CAN FD or something else
    local word = tvb(0, 4):uint()
    -- 29-bit identifiers, remote frames and error frames are no SRDO / GFC
    if band(word, FLAGS_MASK) ~= 0 then return end
    local id = band(word, 0x7FF)
    local dlc = tvb(4, 1):uint()
    if dlc > 8 then return end
    local entry = by_cob[id]
    if id ~= GFC_ID and entry == nil then return end

    local r = results[pinfo.number]
    if r == nil then
        if pinfo.visited then return end
        local at = 8
        local data = {}
        for i = 1, dlc do data[i] = tvb(at + i - 1, 1):uint() end
        r = { errors = {}, id = id, dlc = dlc, data_at = at }
        if id == GFC_ID then
            r.gfc = true
            r.status = (dlc == 0) and "GFC (global fail-safe command)" or
                string.format("identifier 0x001 with DLC %d (no GFC)", dlc)
        else
            r.n = entry.n
            r.inverted = entry.inverted
            check_frame(r, entry.n, entry.inverted, micros(pinfo), dlc, data, pinfo.number)
        end
        results[pinfo.number] = r
    end

    local at = r.data_at
    local sub = tree:add(proto, tvb(at, r.dlc))
    if r.gfc then
        pinfo.cols.protocol = "GFC"
        sub:add(f_kind, "GFC")
        if r.dlc ~= 0 then sub:add_proto_expert_info(e_gfc) end
        sub:add(f_status, r.status)
        pinfo.cols.info = r.status
        sub:append_text(": " .. r.status)
        return
    end
    local c = srdo_cfg[r.n]
    pinfo.cols.protocol = "SRDO"
    sub:add(f_kind, r.inverted and "SRDO inverted data" or "SRDO normal data")
    sub:add(f_number, r.n)
    sub:add(f_cob, r.id)
    sub:add(f_dlc, r.dlc)
    if r.dlc > 0 then sub:add(f_data, tvb(at, r.dlc)) end
    if r.partner ~= nil then sub:add(f_partner, r.partner) end
    if r.gap_ms ~= nil then sub:add(f_gap, r.gap_ms) end
    if r.cycle_ms ~= nil then sub:add(f_cycle, r.cycle_ms) end
    local status = r.status
    if #r.errors > 0 then
        local texts = {}
        for i, e in ipairs(r.errors) do
            texts[i] = e.text
            sub:add_proto_expert_info(e.expert, e.text)
        end
        status = table.concat(texts, "; ")
    end
    status = status or string.format("SRDO %d", r.n)
    sub:add(f_status, status)
    sub:add(f_ok, r.ok == true)
    sub:add(string.format("Limits: SCT %d ms, SRVT %d ms%s (%s)", c.sct_ms, c.srvt_ms,
        c.dlc and string.format(", DLC %d", c.dlc) or "", c.source))
    if config_note ~= nil then sub:add(config_note) end
    sub:append_text(": " .. status)
    local half = r.inverted and "inverted" or "normal"
    local bytes = {}
    for i = 1, r.dlc do bytes[i] = tvb(at + i - 1, 1):uint() end
    pinfo.cols.info = string.format("%s [%s %03X: %s]", status, half, r.id, hex(bytes))
end

-- Link type 227 goes through this dissector, which hands every frame to
-- the SocketCAN dissector first.
encap_table:add(wtap_encaps.SOCKETCAN, proto)
