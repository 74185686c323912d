#include "WorkOffsetStore.h"
#include <memory>

namespace stepdeck::program {

namespace {
QMap<QString, double> offsetsOf(const QVariantMap& axes)
{
    QMap<QString, double> out;
    for (auto it = axes.cbegin(); it != axes.cend(); ++it) {
        bool ok = false;
        const double value = it.value().toDouble(&ok);
        if (ok && qIsFinite(value) && value != 0.0)
            out.insert(it.key(), value);
    }
    return out;
}

QVariantMap variantOf(const QMap<QString, double>& offsets)
{
    QVariantMap axes;
    for (auto it = offsets.cbegin(); it != offsets.cend(); ++it)
        axes.insert(it.key(), it.value());
    return axes;
}
} // namespace

bool StoredOffsets::isEmpty() const
{
    for (const QMap<QString, double>& s : systems)
        if (!s.isEmpty())
            return false;
    return active == 0;
}

std::unique_ptr<QSettings> WorkOffsetStore::windowSettings()
{
    return std::make_unique<QSettings>(QStringLiteral("StepDeck"), QStringLiteral("StepDeck"));
}

StoredOffsets WorkOffsetStore::load(const QSettings& settings, const QString& absolutePath)
{
    StoredOffsets out;
    if (absolutePath.isEmpty())
        return out;
    out.systems[0] = offsetsOf(settings.value(settingsKey()).toMap().value(absolutePath).toMap());
    const QVariantMap more = settings.value(systemsKey()).toMap().value(absolutePath).toMap();
    for (int i = 1; i < kCoordinateSystems; ++i)
        out.systems[size_t(i)] = offsetsOf(more.value(coordinateSystemWord(i)).toMap());
    const int active = more.value(QStringLiteral("active"), 0).toInt();
    out.active = active >= 0 && active < kCoordinateSystems ? active : 0;
    return out;
}

void WorkOffsetStore::save(QSettings& settings, const QString& absolutePath, const StoredOffsets& o)
{
    if (absolutePath.isEmpty())
        return;
    QVariantMap files = settings.value(settingsKey()).toMap();
    if (o.systems[0].isEmpty())
        files.remove(absolutePath);
    else
        files.insert(absolutePath, variantOf(o.systems[0]));
    settings.setValue(settingsKey(), files);
    QVariantMap more;
    for (int i = 1; i < kCoordinateSystems; ++i)
        if (!o.systems[size_t(i)].isEmpty())
            more.insert(coordinateSystemWord(i), variantOf(o.systems[size_t(i)]));
    if (o.active != 0)
        more.insert(QStringLiteral("active"), o.active);
    QVariantMap systems = settings.value(systemsKey()).toMap();
    if (more.isEmpty())
        systems.remove(absolutePath);
    else
        systems.insert(absolutePath, more);
    settings.setValue(systemsKey(), systems);
}

} // namespace stepdeck::program
