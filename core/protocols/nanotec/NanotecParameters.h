#pragma once
#include "NanotecHostDrive.h"
#include "NanotecSchema.h"
#include "NanotecSteps.h"
#include "model/CommandResult.h"
#include <QCoreApplication>
#include <QMap>

namespace stepdeck::nanotec {

class NanotecController;
class NanotecExchange;

// Parameters of Nanotec drives. Every write is echoed by the drive even when the value is
// invalid, and invalid values are silently ignored ("Antwort der Firmware" of each command):
// only reading the value back with 'Z' confirms a write.
class NanotecParameters
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecController)

public:
    explicit NanotecParameters(NanotecController& controller);

    using Cache = std::shared_ptr<QMap<QByteArray, qint64>>;

    void readParameters(RequestId id, const QStringList& names);
    void writeParameters(RequestId id, const ParameterSet& values, bool verify);
    Step readStep(Axis axis, const ParamDef& def, std::function<void(qint64)> sink, Cache cache);
    Step writeStep(Axis axis, const ParamDef& def, qint64 wire);
    Step verifyStep(Axis axis, const ParamDef& def, qint64 expected, Cache cache);

private:
    void noteWritten(HostDrive& d, const ParamDef& def, qint64 wire);
    QList<Step> motorAddressSteps(Axis axis, int address, bool verify);
    // Why a parameter write is refused before anything is sent (empty: it is not).
    QString writeRefusal(const ParameterSet& values) const;

    NanotecController& m_ctl;
    NanotecExchange& m_link;
};

} // namespace stepdeck::nanotec
