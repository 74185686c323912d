#pragma once
// SHELL: replaced by the real adapter (issue #2, section 3).
#include "controller/Controller.h"

namespace stepdeck::elab {

class ElabController : public Controller
{
    Q_OBJECT
public:
    ElabController(Transport* transport, const ControllerOptions& options,
                   QObject* parent = nullptr);
    QString modelId() const override { return QStringLiteral("elab"); }
    Capabilities capabilities() const override;
    ParameterSchema schema() const override;
    void openLink(RequestId id) override { finishError(id, ErrorKind::Unsupported, "shell"); }
    void closeLink() override {}
    void readParameters(RequestId id, const QStringList&) override { openLink(id); }
    void writeParameters(RequestId id, const ParameterSet&, bool) override { openLink(id); }
    void moveRelative(RequestId id, const AxisVector&) override { openLink(id); }
    void reference(RequestId id, const QMap<Axis, int>&) override { openLink(id); }
    void stop(RequestId id) override { openLink(id); }
    void panic(RequestId id) override { openLink(id); }
    void refreshStatus(RequestId id) override { openLink(id); }
    void sendRaw(RequestId id, const QByteArray&) override { openLink(id); }
    void setPollInterval(int) override {}

protected:
    void applyJogVelocity(const AxisVelocities&) override {}
};

} // namespace stepdeck::elab
