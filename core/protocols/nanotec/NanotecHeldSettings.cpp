// What a Nanotec drive is known to hold (NanotecHeldSettings.h).
#include "NanotecHeldSettings.h"
#include "NanotecCodec.h"
#include <cstring>

namespace stepdeck::nanotec {

namespace {
// Settings that change nothing but their own value: travel 's' (6.7), frequencies 'u', 'o',
// 'n' (6.8-6.10), ramp 'b' (6.11), direction 'd' (6.12). A '!', 'p', 'y' (load record), 'm'
// (address) and everything else may change more than one value and forgets the drive.
constexpr char kPlainSettings[] = "sounbd";
} // namespace

bool NanotecHeldSettings::isRead(const QByteArray& body)
{
    return body.startsWith('Z') || body == "$" || body == "C" || body == "v";
}

char NanotecHeldSettings::plainSettingKey(const QByteArray& body)
{
    if (body.size() < 2)
        return 0;
    const char key = body.at(0);
    bool number = false;
    body.mid(1).toLongLong(&number);
    return number && key != 0 && std::strchr(kPlainSettings, key) ? key : 0;
}

void NanotecHeldSettings::onExchange(int address, const QByteArray& body, bool answered,
                                     qint64 nowMs)
{
    if (address == kBroadcast) {
        forgetAll();
        return;
    }
    auto it = m_drives.find(address);
    if (it == m_drives.end())
        return;
    if (!answered || nowMs - it->lastAnswerMs > kMaxSilenceMs) {
        m_drives.erase(it);
        return;
    }
    it->lastAnswerMs = nowMs;
    if (isRead(body) || body == "S")
        return;
    if (body == "A") {
        if (it->values.value('N', -1) != 0)
            m_drives.erase(it);
        return;
    }
    if (const char key = plainSettingKey(body)) {
        it->values.remove(key);
        return;
    }
    m_drives.erase(it);
}

void NanotecHeldSettings::confirm(int address, char key, qint64 value, qint64 nowMs)
{
    Drive& d = m_drives[address];
    if (!d.values.isEmpty() && nowMs - d.lastAnswerMs > kMaxSilenceMs)
        d.values.clear();
    d.values.insert(key, value);
    d.lastAnswerMs = nowMs;
}

bool NanotecHeldSettings::holds(int address, char key, qint64 value, qint64 nowMs) const
{
    const auto it = m_drives.constFind(address);
    if (it == m_drives.constEnd() || nowMs - it->lastAnswerMs > kMaxSilenceMs)
        return false;
    const auto v = it->values.constFind(key);
    return v != it->values.constEnd() && *v == value;
}

} // namespace stepdeck::nanotec
