#pragma once
#include <QCoreApplication>

namespace stepdeck::cli {

// The context of stepdeck-cli's own texts: CliText::tr("...") instead of a file-local tr()
// helper, so that lupdate can read them (issue 10). English: the CLI installs no translator.
class CliText
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::cli::CliText)
};

} // namespace stepdeck::cli
