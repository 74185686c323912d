#include "Translations.h"
#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
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

QString install(QCoreApplication* app, const QString& code)
{
    const QString lang = effective(code);
    QLocale::setDefault(QLocale(lang));
    if (lang == QLatin1String("en"))
        return lang;
    auto* own = new QTranslator(app);
    if (own->load(QStringLiteral(":/i18n/stepdeck_%1.qm").arg(lang)))
        QCoreApplication::installTranslator(own);
    else
        delete own;
    auto* qt = new QTranslator(app);
    if (qt->load(QStringLiteral("qtbase_%1").arg(lang),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    else
        delete qt;
    return lang;
}

} // namespace stepdeck::ui::translations
