#pragma once
#include <QString>
#include <QStringList>

class QCoreApplication;

namespace stepdeck::ui {

// English (the source language) and German. The system locale chooses unless the operator
// picked a language in the View menu (stored in QSettings, applied at the next start).
namespace translations {
QStringList available();                   // {"en", "de"}
QString languageName(const QString& code); // "English", "Deutsch"
QString configured();                      // "" = follow the system locale
void setConfigured(const QString& code);
QString effective(const QString& configured); // the code actually used
// Installs the application's translators (English: its plural forms) and Qt's own, in place of
// those an earlier install() put in; returns the code in use.
QString install(QCoreApplication* app, const QString& code);
} // namespace translations

} // namespace stepdeck::ui
