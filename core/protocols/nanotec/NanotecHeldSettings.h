#pragma once
#include <QByteArray>
#include <QHash>
#include <QMap>

namespace stepdeck::nanotec {

// The settings a drive is known to hold because a read-back ('Z', 5.19) showed them, for as
// long as nothing can have changed them since (issue 30: a chain of chords on the same drives
// need not write and read back '!1' and 'p2' before every chord; each costs an exchange of
// about 6 ms at 19200 baud).
//
// A held value is forgotten when:
// - the drive is sent anything but a read ('Z…', '$', 'C', 'v'), a stop ('S'), a start ('A')
//   while its follow-up record 'N' (6.16) is held at 0 (a follow-up record loads other
//   settings), or a setting of a key without side effects (that key alone is forgotten: only
//   a read-back proves a setting);
// - any exchange with it ends without its answer (silence, garbage, cancelled), or a
//   broadcast goes out (no answer comes back to tell what it did);
// - it has not answered for kMaxSilenceMs. Reading of 5.32 stated here: at power-on the
//   bootloader waits half a second for '@A' before the firmware runs, so a drive that reset
//   (and so fell back to its EEPROM settings) has not answered anything for at least 0.5 s.
//   A shorter silence cannot hide a reset.
// Pure bookkeeping: the controller feeds it every completed exchange and the clock.
class NanotecHeldSettings
{
public:
    static constexpr qint64 kMaxSilenceMs = 400; // < the 500 ms of 5.32

    // Every completed exchange; answered: the drive's own matching reply came back.
    void onExchange(int address, const QByteArray& body, bool answered, qint64 nowMs);
    // A read-back showed the drive holds key = value.
    void confirm(int address, char key, qint64 value, qint64 nowMs);
    bool holds(int address, char key, qint64 value, qint64 nowMs) const;
    void forget(int address) { m_drives.remove(address); }
    void forgetAll() { m_drives.clear(); }

private:
    struct Drive
    {
        QMap<char, qint64> values;
        qint64 lastAnswerMs = 0;
    };
    // The key a body sets when it is a setting without side effects on other keys.
    static char plainSettingKey(const QByteArray& body);
    static bool isRead(const QByteArray& body);

    QHash<int, Drive> m_drives;
};

} // namespace stepdeck::nanotec
