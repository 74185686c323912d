#pragma once
// SHELL: replaced by the real simulator (issue #2, section 4).
#include "sim/Simulator.h"

namespace stepdeck::elab {

class ElabSimulator : public Simulator
{
    Q_OBJECT
public:
    explicit ElabSimulator(const SimulatorOptions& options, QObject* parent = nullptr)
        : Simulator(options, parent)
    {
    }
    QString modelId() const override { return QStringLiteral("elab"); }
    void receive(const QByteArray&) override {}
};

} // namespace stepdeck::elab
