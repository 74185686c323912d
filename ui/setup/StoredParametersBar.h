#pragma once
#include "model/CommandResult.h"
#include "model/ParameterSchema.h"
#include <QWidget>

class QLabel;
class QPushButton;

namespace stepdeck::ui {

class MachineContext;
class SetupPage;

// For controllers that keep power-on values (Capabilities::storedParameters, EMIS "##"
// system parameters): store the setup form's values as power-on values, and read the stored
// values into the form. Hidden for every other model.
class StoredParametersBar : public QWidget
{
    Q_OBJECT
public:
    StoredParametersBar(MachineContext* context, SetupPage* page, QWidget* parent = nullptr);

    QPushButton* storeButton() const { return m_store; }
    QPushButton* readButton() const { return m_read; }
    QString messageText() const;

public Q_SLOTS:
    // ask: confirm with the technician first (tests pass false). false: nothing sent.
    // ask: a non-modal question first; the store is sent once it is answered Yes.
    bool store(bool ask = true);
    void readStored();

private:
    void refresh();
    void onResult(const CommandResult& result);
    void setMessage(const QString& text, bool error);
    void sendStore(const ParameterSet& set);

    MachineContext* m_context;
    SetupPage* m_page;
    QPushButton* m_store;
    QPushButton* m_read;
    QLabel* m_message;
    RequestId m_pendingStore = 0;
    RequestId m_pendingRead = 0;
};

} // namespace stepdeck::ui
