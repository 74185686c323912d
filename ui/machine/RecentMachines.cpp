#include "RecentMachines.h"
#include <QFileInfo>
#include <QSettings>

namespace stepdeck::ui::recentmachines {

namespace {
const QString kRecent = QStringLiteral("machines/recent");

QString absolute(const QString& path)
{
    return QFileInfo(path).absoluteFilePath();
}
} // namespace

QStringList list()
{
    QStringList paths = QSettings().value(kRecent).toStringList();
    paths.removeAll(QString());
    paths.removeDuplicates();
    return paths.mid(0, kMaxRecentMachines);
}

void add(const QString& path)
{
    if (path.trimmed().isEmpty())
        return;
    const QString file = absolute(path);
    QStringList paths = list();
    paths.removeAll(file);
    paths.prepend(file);
    QSettings().setValue(kRecent, paths.mid(0, kMaxRecentMachines));
}

void remove(const QString& path)
{
    QStringList paths = list();
    paths.removeAll(absolute(path));
    QSettings().setValue(kRecent, paths);
}

void clear()
{
    QSettings().remove(kRecent);
}

} // namespace stepdeck::ui::recentmachines
