#include "Translations.h"
#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QPointer>
#include <QSettings>
#include <QTranslator>

namespace stepdeck::ui::translations {

QStringList available()
{
    return {QStringLiteral("en"), QStringLiteral("de")};
}

QString languageName(const QString& code)
{
    if (code == QLatin1String("de"))
        return QStringLiteral("Deutsch");
    return QStringLiteral("English");
}

QString configured()
{
    return QSettings().value(QStringLiteral("ui/language")).toString();
}

void setConfigured(const QString& code)
{
    QSettings().setValue(QStringLiteral("ui/language"), code);
}

QString effective(const QString& configuredCode)
{
    if (available().contains(configuredCode))
        return configuredCode;
    const QString system = QLocale::system().name().left(2);
    return available().contains(system) ? system : QStringLiteral("en");
}

namespace {
// What install() put in place, taken out again by the next install(): switching back to
// English leaves no German behind.
QList<QPointer<QTranslator>>& installedTranslators()
{
    static QList<QPointer<QTranslator>> list;
    return list;
}

void installTranslator(QCoreApplication* app, const QString& file, const QString& directory)
{
    auto* translator = new QTranslator(app);
    if (!translator->load(file, directory)) {
        delete translator;
        return;
    }
    QCoreApplication::installTranslator(translator);
    installedTranslators() << translator;
}
} // namespace

QString install(QCoreApplication* app, const QString& code)
{
    const QString lang = effective(code);
    QLocale::setDefault(QLocale(lang));
    for (const QPointer<QTranslator>& t : std::as_const(installedTranslators())) {
        if (t) {
            QCoreApplication::removeTranslator(t);
            delete t;
        }
    }
    installedTranslators().clear();
    // English too: its catalogue holds the plural forms ("1 error", "2 errors"); without it
    // the source's "%n error(s)" showed.
    installTranslator(app, QStringLiteral(":/i18n/stepdeck_%1.qm").arg(lang), QString());
    if (lang != QLatin1String("en"))
        installTranslator(app, QStringLiteral("qtbase_%1").arg(lang),
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    return lang;
}

} // namespace stepdeck::ui::translations
