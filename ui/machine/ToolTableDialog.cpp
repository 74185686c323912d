#include "ToolTableDialog.h"
#include "program/MachineTools.h"
#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepdeck::ui {

ToolTableDialog::ToolTableDialog(program::MachineTools* tools, QWidget* parent)
    : QDialog(parent), m_tools(tools), m_editor(new QPlainTextEdit(this)), m_error(new QLabel(this))
{
    setWindowTitle(tr("Tool table"));
    setObjectName(QStringLiteral("toolTableDialog"));
    auto* layout = new QVBoxLayout(this);
    auto* help = new QLabel(tr("One tool a line, as in LinuxCNC's tool.tbl: T<number> Z<length> "
                               "D<diameter> ;text. G43 offsets Z by the length (in Z's unit); M6 "
                               "shows the text when it asks for the tool."),
                            this);
    help->setWordWrap(true);
    layout->addWidget(help);
    m_editor->setObjectName(QStringLiteral("toolTableText"));
    m_editor->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_editor->setPlaceholderText(QStringLiteral("T1 P1 Z12.5 D6 ;6 mm end mill"));
    m_editor->setPlainText(QString::fromUtf8(tools->text()));
    layout->addWidget(m_editor, 1);
    // One line reserved for the error, so that it never moves the buttons.
    m_error->setObjectName(QStringLiteral("toolTableError"));
    m_error->setFixedHeight(m_error->fontMetrics().height() + 4);
    m_error->setStyleSheet(QStringLiteral("QLabel { color: #b00020; }"));
    layout->addWidget(m_error);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        if (save())
            accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(tools, &program::MachineTools::machineChanged, this, &ToolTableDialog::machineChanged);
    resize(520, 360);
}

void ToolTableDialog::machineChanged()
{
    const bool edited = m_editor->document()->isModified();
    m_editor->setPlainText(QString::fromUtf8(m_tools->text()));
    m_editor->document()->setModified(false);
    if (edited)
        m_error->setText(tr("Another machine was opened: its table is shown; the unsaved edits "
                            "were for the previous one and are dropped."));
    else
        m_error->clear();
}

QString ToolTableDialog::errorText() const
{
    return m_error->text();
}

bool ToolTableDialog::save()
{
    QList<program::ProgramError> errors;
    if (m_tools->setText(m_editor->toPlainText().toUtf8(), &errors)) {
        m_error->clear();
        return true;
    }
    m_error->setText(errors.isEmpty() ? tr("The table was not saved.")
                                      : tr("Not saved: %1").arg(errors.first().text()));
    return false;
}

} // namespace stepdeck::ui
