// Command handling of a simulated Nanotec drive: settings, reads, records, error memory.
// Motion lives in NanotecDriveMotion.cpp.
#include "NanotecDrive.h"

namespace stepdeck::nanotec {

namespace {
// Commands that take a value (sections 5-7) and those that take none.
const QByteArray kValueCommands("irgm!leaUFqOXLhk/\\KYJzpsuonbdtWPN=fQR%y>|");
const QByteArray kPlainCommands("DEICcM$vAS+-T ");
const QByteArray kFirmware("SMCI47-S_RS485_04-12-2008");

bool oneOf(qint64 v, std::initializer_list<qint64> allowed)
{
    for (qint64 a : allowed) {
        if (v == a)
            return true;
    }
    return false;
}

bool inRange(qint64 v, qint64 lo, qint64 hi)
{
    return v >= lo && v <= hi;
}

bool onlyBits(qint64 v, qint64 mask)
{
    return v >= 0 && (v & ~mask) == 0;
}

// 5.6: exactly one bit set inside `mask`.
bool exactlyOne(qint64 v, qint64 mask)
{
    const qint64 g = v & mask;
    return g != 0 && (g & (g - 1)) == 0;
}
} // namespace

NanotecDrive::NanotecDrive(int address) : m_address(address)
{
    const QList<QPair<char, qint64>> defaults{
        {'i', 50},      {'r', 25},      {'g', 2},    {'!', 1}, {'l', 5154}, {'e', 0},
        {'a', 18},      {'U', 1},       {'F', 1},    {'q', 0}, {'O', 2},    {'X', 2},
        {'L', 0x3003F}, {'h', 0x3003F}, {'k', 0},    {'/', 0}, {'\\', 0},   {'K', 0},
        {'Y', 0},       {'J', 0},       {'z', 0},    {'p', 1}, {'s', 400},  {'u', 400},
        {'o', 1000},    {'n', 1000},    {'b', 2364}, {'d', 0}, {'t', 0},    {'W', 1},
        {'P', 0},       {'N', 0},       {'=', 0},    {'f', 0}, {'Q', -100}, {'R', 100},
        {'%', 0}};
    for (const auto& d : defaults)
        m_params.insert(d.first, d.second);
    const char* longKeys[] = {"CL_ramp_mode",
                              "brake_ta",
                              "brake_tb",
                              "brake_tc",
                              "CL_enable",
                              "CL_position_window",
                              "CL_position_window_time",
                              "CL_following_error_window",
                              "CL_following_error_timeout",
                              "CL_rotenc_rev"};
    for (const char* k : longKeys)
        m_long.insert(k, 0);
    m_long["CL_rotenc_rev"] = 1;
    m_long["CL_motor_pp"] = 50;
    m_long["CL_rotenc_inc"] = 2000;
    for (const char* term : {"KP_v", "KI_v", "KD_v", "KP_s", "KI_s", "KD_s"}) {
        m_long[QByteArray("CL_") + term + "_Z"] = 0;
        m_long[QByteArray("CL_") + term + "_N"] = 0;
    }
    RecordData ram;
    for (char c : recordFieldOrder())
        ram.fields << qMakePair(c, m_params.value(c));
    for (int n = 1; n <= kRecordCount; ++n) {
        m_eeprom[n] = ram;
        m_eeprom[n].record = n;
    }
}

NanotecDrive::Answer NanotecDrive::handle(const QByteArray& body)
{
    Answer a;
    if (body.isEmpty() || body.startsWith("@A"))
        return a; // 5.32: the firmware itself does not answer the bootloader command
    const char c = body.at(0);
    if (c == ':') {
        a = handleLong(body);
    } else if (c == 'Z') {
        a = handleRead(body);
    } else if (kValueCommands.contains(c)) {
        a.body = handleValue(c, body);
    } else if (kPlainCommands.contains(c)) {
        if (body.size() > 1)
            return {body + '?', false};
        a.body = handlePlain(c, body);
    } else {
        a.body = body + '?';
    }
    if (m_silentMode)
        a.body.clear();
    return a;
}

QByteArray NanotecDrive::handleValue(char c, const QByteArray& body)
{
    qint64 v = 0;
    const QByteArray rest = body.mid(1);
    QByteArray answer;
    if (!parseNumber(rest, &v)) {
        answer = body + '?'; // "#1/\r" -> "001/?\r" (1.1)
    } else if (c == '|') {
        // 6.4: '|0' silences the drive (it still executes), '|1' brings answers back.
        if (v == 0 || v == 1)
            m_silentMode = v == 0;
        answer = body;
    } else {
        if (validSetting(c, v) && !faults.ignoredSettings.contains(c))
            applySetting(c, v);
        answer = body; // echoed even when invalid, and then ignored
    }
    return answer;
}

QByteArray NanotecDrive::handlePlain(char c, const QByteArray& body)
{
    QByteArray answer;
    answer = body;
    switch (c) {
    case '$':
        answer += QByteArray::number(statusWord());
        break;
    case 'C':
        answer += QByteArray::number(position());
        break;
    case 'I':
        answer += QByteArray::number(encoderPosition());
        break;
    case 'M':
        answer += QByteArray::number(m_address);
        break;
    case 'E':
        answer += QByteArray::number(m_lastSlot);
        break;
    case 'v':
        answer = "v " + kFirmware;
        break;
    case ' ':
        answer = ' ' + kFirmware;
        break;
    case 'A':
        start();
        break;
    case 'S':
        stopNow();
        break;
    case 'D': // 5.14: clear the error, take over the encoder position
        m_positionError = false;
        m_count = double(encoderPosition());
        break;
    case 'c': // 5.18: the current position becomes the reference position
        m_count = 0;
        m_encoderOffset = m_physical;
        break;
    case '+':
    case '-':
        if (m_run == Run::Speed)
            m_params['o'] =
                qBound(qint64(60), m_params['o'] + (c == '+' ? 100 : -100), qint64(25000));
        break;
    case 'T': // 7.8: the flag positioning run now travels 's' more at speed 'n'
        if (m_run == Run::Flag && !m_flagTriggered) {
            m_flagTriggered = true;
            m_target = m_count + m_dir * double(qAbs(m_params['s']));
            m_topSpeed = double(m_params['n']);
        }
        break;
    default:
        break;
    }
    return answer;
}

NanotecDrive::Answer NanotecDrive::handleLong(const QByteArray& body)
{
    const QByteArray key = commandKey(body).mid(1);
    const QByteArray rest = body.mid(key.size() + 1);
    Answer unknown{":?", true}; // 1.2: "ID:?"
    if (!m_long.contains(key))
        return unknown;
    if (rest.isEmpty())
        return {':' + key + formatSigned(m_long[key]), true};
    qint64 v = 0;
    if (!rest.startsWith('=') || !parseNumber(rest.mid(1), &v))
        return unknown;
    bool valid = false;
    if (key == "CL_ramp_mode")
        valid = inRange(v, 0, 1);
    else if (key == "CL_enable")
        // 8.1: '1' needs the special reference run '!8' since power-on (and the calibration run
        // '!101' for this motor); without them it is ignored.
        valid = v == 0 || (v == 1 && m_closedLoop.acceptsEnable());
    else if (key == "CL_position_window" || key == "CL_following_error_window" ||
             key == "CL_rotenc_inc" || key == "CL_rotenc_rev")
        valid = inRange(v, 0, 4294967295LL);
    else if (key.endsWith("_N"))
        valid = inRange(v, 0, 15);
    else
        valid = inRange(v, 0, 65535);
    if (key == "CL_motor_pp")
        valid = inRange(v, 1, 65535);
    if (valid) {
        m_long[key] = v;
        if (key == "CL_motor_pp") // 8.6: CL_motor_pp = 900 / step angle
            m_params['a'] = 900 / v;
    }
    return {body, true};
}

NanotecDrive::Answer NanotecDrive::handleRead(const QByteArray& body)
{
    const Answer unknown{body + '?', false};
    const QByteArray r = body.mid(1);
    if (r.startsWith('E')) {
        // 5.15: "ZE<slot>" -> "ZE<slot><code>"
        qint64 slot = 0;
        if (!parseNumber(r.mid(1), &slot) || !inRange(slot, 1, kErrorSlots))
            return unknown;
        return {body + QByteArray::number(m_errors[slot]), false};
    }
    int digits = 0;
    while (digits < r.size() && r.at(digits) >= '0' && r.at(digits) <= '9')
        ++digits;
    const int record = digits ? r.left(digits).toInt() : 0;
    if (r.size() != digits + 1 || record > kRecordCount || (digits && record == 0))
        return unknown;
    const char c = r.at(digits);
    if (c == '|') {
        RecordData data;
        data.record = record;
        if (record > 0) {
            data.fields = m_eeprom[record].fields;
        } else {
            for (char f : recordFieldOrder())
                data.fields << qMakePair(f, m_params.value(f));
        }
        return {formatRecord(data), false};
    }
    if (record > 0) {
        const auto v = m_eeprom[record].value(c);
        return v ? Answer{body + QByteArray::number(*v), false} : unknown;
    }
    if (c == 'm')
        return {body + QByteArray::number(m_address), false};
    if (c == 'Y')
        return {body + inputsWord(), false};
    if (!kValueCommands.contains(c) || c == 'y' || c == '>' || c == '|')
        return unknown;
    return {body + QByteArray::number(m_params.value(c)), false};
}

bool NanotecDrive::validSetting(char cmd, qint64 v) const
{
    switch (cmd) {
    case 'i':
    case 'r':
        return inRange(v, 0, 150);
    case 'g':
        return oneOf(v, {1, 2, 4, 5, 8, 10, 16, 32, 64, 255});
    case 'm':
        return inRange(v, kMinAddress, kMaxAddress);
    case '!':
        // 5.5 lists modes 1..6 (its "1 bis 5" contradicts its own list); 8.1 adds mode 8, the
        // closed-loop reference run, and 101, the calibration run. No change during a run.
        return (inRange(v, 1, 6) || v == 8 || v == 101) && ready();
    case 'l':
        return onlyBits(v, 0xFFFF) && exactlyOne(v, 0x0003) && exactlyOne(v, 0x003C) &&
               exactlyOne(v, 0x0600) && exactlyOne(v, 0x7800);
    case 'e':
    case 'q':
    case 'd':
    case 't':
    case 'J':
        return inRange(v, 0, 1);
    case 'a':
        return oneOf(v, {9, 18});
    case 'U':
        return inRange(v, 0, 2);
    case 'F':
    case 'y':
    case '>':
        return inRange(v, 1, kRecordCount);
    case 'O':
        return inRange(v, 0, 255);
    case 'X':
    case '=':
    case '%':
        return inRange(v, 0, 100);
    case 'L':
    case 'h':
        return onlyBits(v, 0x3003F);
    case 'k':
    case '/':
    case '\\':
        return onlyBits(v, 0x3F);
    case 'K':
        return inRange(v, 0, 10);
    case 'Y':
        return onlyBits(v, 0x30000);
    case 'z':
        return inRange(v, 0, 9999);
    case 'p': {
        // 6.6: p=2 is "nicht belegt" outside the positioning mode.
        const qint64 mode = m_params.value('!');
        return inRange(v, 1, 4) && !(v == 2 && mode >= 2 && mode <= 4);
    }
    case 's':
        return inRange(v, -2147483648LL, 2147483647LL);
    case 'u':
    case 'o':
    case 'n':
        return inRange(v, 60, 25000);
    case 'b':
    case 'P':
        return inRange(v, cmd == 'b' ? 1 : 0, 65535);
    case 'W':
        return inRange(v, 0, 254);
    case 'N':
        return inRange(v, 0, kRecordCount);
    case 'f':
        return inRange(v, 0, 16);
    case 'Q':
    case 'R':
        return inRange(v, -100, 100);
    default:
        return false;
    }
}

void NanotecDrive::applySetting(char cmd, qint64 v)
{
    switch (cmd) {
    case 'm':
        m_address = int(v);
        return; // the echo still goes out from the old address
    case 'y':
        loadRecord(int(v));
        return;
    case '>': {
        RecordData data;
        data.record = int(v);
        for (char f : recordFieldOrder())
            data.fields << qMakePair(f, m_params.value(f));
        m_eeprom[v] = data;
        return;
    }
    case '/':
    case '\\':
        m_params['k'] |= v; // 5.27/5.28: switches the interrupt on as well
        break;
    case 'a':
        m_long["CL_motor_pp"] = 900 / v;
        break; // 8.6
    default:
        break;
    }
    m_params[cmd] = v;
}

void NanotecDrive::loadRecord(int n)
{
    for (const auto& f : m_eeprom[n].fields)
        m_params[f.first] = f.second;
}

quint8 NanotecDrive::statusWord() const
{
    DriveState s;
    s.ready = ready();
    s.zeroReached = position() == 0;
    s.positionError = m_positionError;
    // Bits 4-6 hold modes 0..7 (5.21); the closed-loop runs 8 and 101 do not fit, so they
    // read as 0 "unbenutzt" (our reading: the manual says nothing about them there).
    const qint64 mode = m_params.value('!');
    s.mode = mode >= 1 && mode <= 6 ? int(mode) : 0;
    return encodeStatus(s);
}

QByteArray NanotecDrive::inputsWord() const
{
    // 5.30: inputs 1-6 in bits 0-5 (input 6 carries the external switch, 5.7), bit 6 is 0 at
    // the encoder index mark, outputs as set in bits 16-17.
    const bool actuated = externalSwitchActuated();
    const bool level = m_params.value('e') == 0 ? !actuated : actuated;
    qint64 w = (level ? 0x20 : 0) | (atIndexMark() ? 0 : 0x40);
    w |= m_params.value('Y') & 0x30000;
    return QByteArray::number(w);
}

void NanotecDrive::injectPositionError()
{
    m_positionError = true;
    pushError(error::Position);
}

void NanotecDrive::pushError(int code)
{
    // 5.15: 32 slots used as a ring; after slot 32 the next error goes to slot 1.
    m_lastSlot = m_lastSlot >= kErrorSlots ? 1 : m_lastSlot + 1;
    m_errors[m_lastSlot] = code;
}

} // namespace stepdeck::nanotec
