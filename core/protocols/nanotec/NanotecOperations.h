#pragma once
#include "NanotecHostDrive.h"
#include "NanotecSteps.h"
#include "model/CommandResult.h"
#include <QCoreApplication>
#include <QVariantMap>

namespace stepdeck::nanotec {

class NanotecController;
class NanotecExchange;

// The model-specific operations of a Nanotec bus (NanotecController.h lists them), the bus
// scan ('v' to every address, 5.22) and the console.
class NanotecOperations
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecController)

public:
    explicit NanotecOperations(NanotecController& controller);

    void modelOperation(RequestId id, const QString& name, const QVariantMap& args);
    void sendRaw(RequestId id, const QByteArray& bytes);
    // Runs the scan asked for while the port was closed, now that it is open.
    void runPendingScan();

private:
    void startScan(RequestId id, const QVariantMap& args);
    void scan(RequestId id, int first, int last, int timeoutMs);
    void driveOperation(RequestId id, const QString& name, Axis axis, const QVariantMap& args);
    void simple(RequestId id, Axis axis, const QByteArray& body);
    void resetPosition(RequestId id, Axis axis);
    void startRecord(RequestId id, Axis axis, int record);

    NanotecController& m_ctl;
    NanotecExchange& m_link;
};

} // namespace stepdeck::nanotec
