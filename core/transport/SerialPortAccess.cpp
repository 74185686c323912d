#include "SerialPortAccess.h"
#include <grp.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace stepdeck {

namespace {
bool processHasGroup(gid_t gid)
{
    if (getegid() == gid)
        return true;
    const int count = getgroups(0, nullptr);
    if (count <= 0)
        return false;
    std::vector<gid_t> groups(static_cast<size_t>(count));
    const int got = getgroups(count, groups.data());
    for (int i = 0; i < got; ++i) {
        if (groups[static_cast<size_t>(i)] == gid)
            return true;
    }
    return false;
}
} // namespace

SerialPortAccess SerialPortAccess::probe(const QString& device)
{
    SerialPortAccess a;
    a.device = device;
    const QByteArray path = device.toLocal8Bit();
    a.accessible = ::access(path.constData(), R_OK | W_OK) == 0;
    if (const passwd* pw = getpwuid(geteuid()))
        a.userName = QString::fromLocal8Bit(pw->pw_name);
    struct stat st = {};
    if (::stat(path.constData(), &st) != 0)
        return a;
    a.inGroupNow = processHasGroup(st.st_gid);
    const group* gr = getgrgid(st.st_gid);
    if (!gr)
        return a;
    a.deviceGroup = QString::fromLocal8Bit(gr->gr_name);
    const QByteArray user = a.userName.toLocal8Bit();
    for (char** member = gr->gr_mem; member && *member && !user.isEmpty(); ++member) {
        if (user == *member)
            a.groupListsUser = true;
    }
    return a;
}

QString SerialPortAccess::deniedText() const
{
    if (accessible)
        return tr("serial port %1 is in use by another program").arg(device);
    const QString group = deviceGroup.isEmpty() ? defaultGroup() : deviceGroup;
    const QString user = userName.isEmpty() ? QStringLiteral("$USER") : userName;
    if (inGroupNow) {
        return tr("serial port %1: access denied although you are in its group '%2': check "
                  "the device's permissions (ls -l %1)")
            .arg(device, group);
    }
    if (groupListsUser) {
        return tr("serial port %1: access denied: you were added to the group '%2', but this "
                  "session does not have it yet: log out and in again")
            .arg(device, group);
    }
    return tr("serial port %1: access denied: your user is not in the group '%2' that owns "
              "it. Join it (sudo adduser %3 %2), then log out and in again")
        .arg(device, group, user);
}

} // namespace stepdeck
