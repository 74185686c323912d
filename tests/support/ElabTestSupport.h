#pragma once
// Test helpers shared by the E-LAB tests.
#include "protocols/elab/ElabCodec.h"
#include <QByteArray>
#include <QString>

namespace stepdeck::elab::testing {

// Bytes from the manual's notation ("<ESC>S0064,0064;0064."), so tests read like the manual.
inline QByteArray bytes(const char* mnemonics)
{
    QByteArray out;
    QString error;
    if (!fromMnemonics(QString::fromLatin1(mnemonics), &out, &error))
        qFatal("bad mnemonic in test: %s", qPrintable(error));
    return out;
}

} // namespace stepdeck::elab::testing
