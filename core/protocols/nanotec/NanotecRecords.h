#pragma once
#include "NanotecHostDrive.h"
#include "NanotecSteps.h"
#include "model/CommandResult.h"
#include <QCoreApplication>
#include <QVariantMap>

namespace stepdeck::nanotec {

class NanotecController;
class NanotecExchange;

// Records (section 4, 6.3-6.5) and the error memory (5.15) of a Nanotec drive.
class NanotecRecords
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecController)

public:
    explicit NanotecRecords(NanotecController& controller);

    void readRecord(RequestId id, Axis axis, int record);
    void readAllRecords(RequestId id, Axis axis);
    void writeRecord(RequestId id, Axis axis, int record, const QVariantMap& values);
    void loadOrSaveRecord(RequestId id, Axis axis, int record, bool save);
    void readErrorMemory(RequestId id, Axis axis);

private:
    Step readRecordStep(Axis axis, int record, std::shared_ptr<QVariantMap> out);

    NanotecController& m_ctl;
    NanotecExchange& m_link;
};

} // namespace stepdeck::nanotec
