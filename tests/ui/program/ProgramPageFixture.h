#pragma once
// The Program page's tests' base (tst_programpage, tst_programpagerun): the main window on a
// machine of two simulated controllers on pseudo-terminals (MachineWindowRig: an E-LAB X/Y/Z
// table, 400 steps/mm on X and Y, and a Nanotec rotary axis A), and what they do to the page.
#include "../LaptopScreen.h"
#include "../LayoutChecks.h"
#include "../machine/MachineWindowRig.h"
#include "machine/MachineContext.h"
#include "machine/MachineDro.h"
#include "position/PositionPanel.h"
#include "program/MachineWorkOffsets.h"
#include "program/ProgramControls.h"
#include "program/ProgramEditor.h"
#include "program/ProgramPage.h"
#include "program/ProgramPathView.h"
#include "program/ProgramPreviewView.h"
#include "program/ProgramPromptBanner.h"
#include "safety/SafetyBar.h"
#include <QCheckBox>
#include <QDockWidget>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QTextBlock>

#include "protocols/elab/ElabSimulator.h"

namespace stepdeck::test {

class ProgramPageFixture : public QObject
{
protected:
    ui::MainWindow* window() const { return m_rig.window(); }
    ui::ProgramPage* page() const { return window()->programPage(); }
    program::ProgramRunner* runner() const { return page()->runner(); }
    void setProgram(const QString& text)
    {
        window()->raisePage(page());
        page()->editor()->setPlainText(text);
        page()->checkNow();
        QTRY_VERIFY(!page()->isChecking()); // off the GUI thread
    }
    // A run asked for is first checked off the GUI thread (ProgramStarter): until then the
    // runner still has the state of the run before.
    bool runState(program::RunState state) const
    {
        return runner() && !page()->isStarting() && runner()->state() == state;
    }
    // "stop": the STOP button, "panic": the PANIC button, else Esc in the editor.
    void stopBy(const QString& how)
    {
        if (how == QLatin1String("stop")) {
            window()->safetyBar()->stopButton()->click();
        } else if (how == QLatin1String("panic")) {
            window()->safetyBar()->panicButton()->click();
        } else {
            page()->editor()->setFocus();
            QTRY_VERIFY(page()->editor()->hasFocus());
            QTest::keyClick(page()->editor(), Qt::Key_Escape);
        }
    }

    MachineWindowRig m_rig;
};

} // namespace stepdeck::test
