#include "SetupPage.h"
#include "common/Dialogs.h"
#include "machine/MachineContext.h"
#include "setup/ParameterField.h"
#include "setup/SetupDriveChooser.h"
#include "setup/SetupMessageLine.h"
#include "setup/StoredParametersBar.h"
#include "setup/WritePlan.h"
#include "setup/WritePreview.h"
#include "setup/WriteResultText.h"
#include "setup/WriteWarnings.h"
#include <QCoreApplication>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>

namespace stepdeck::ui {

SetupPage::SetupPage(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_groups(new QVBoxLayout),
      m_read(new QPushButton(tr("Read"), this)), m_write(new QPushButton(tr("Write"), this)),
      m_writeVerify(new QPushButton(tr("Write && verify"), this)),
      m_writeAll(new QPushButton(tr("Write all"), this)), m_info(new QLabel(this)),
      m_message(new SetupMessageLine(this)), m_driveChooser(new SetupDriveChooser(context, this))
{
    auto* defaults = new QPushButton(tr("Defaults"), this);
    auto* save = new QPushButton(tr("Save to file\u2026"), this);
    auto* loadButton = new QPushButton(tr("Load from file\u2026"), this);
    m_write->setObjectName(QStringLiteral("setupWrite"));
    m_writeAll->setObjectName(QStringLiteral("setupWriteAll"));
    m_read->setToolTip(tr("Read the values back from the controller"));
    m_writeVerify->setToolTip(tr("Write, then read back and compare where the protocol can"));
    defaults->setToolTip(tr("Fill the form with the model's default values (nothing is sent)"));
    m_formButtons = {defaults, save, loadButton};

    auto* bar = new QHBoxLayout;
    for (QPushButton* b : {m_read, m_write, m_writeVerify, m_writeAll, defaults})
        bar->addWidget(b);
    bar->addStretch(1);
    bar->addWidget(save);
    bar->addWidget(loadButton);
    m_info->setWordWrap(true);
    m_info->setStyleSheet(QStringLiteral("QLabel { color: palette(dark); }"));
    m_message->setObjectName(QStringLiteral("setupMessage"));
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(new StoredParametersBar(context, this, this)); // hidden unless the model
    layout->addWidget(m_info);                                       // keeps power-on values
    layout->addWidget(m_driveChooser); // a bus of more drives than columns (issue 32)
    layout->addLayout(m_groups, 1);
    layout->addWidget(m_message);

    connect(m_read, &QPushButton::clicked, this, &SetupPage::read);
    connect(m_write, &QPushButton::clicked, this, [this] { write(false, true); });
    connect(m_writeVerify, &QPushButton::clicked, this, [this] { write(true, true); });
    connect(m_writeAll, &QPushButton::clicked, this, [this] { writeAll(false, true); });
    connect(defaults, &QPushButton::clicked, this, &SetupPage::resetToDefaults);
    connect(save, &QPushButton::clicked, this, &SetupPage::saveAs);
    connect(loadButton, &QPushButton::clicked, this, &SetupPage::load);
    connect(context, &MachineContext::modelChanged, this, &SetupPage::rebuild);
    connect(m_driveChooser, &SetupDriveChooser::shownAxesChanged, this, &SetupPage::showDrives);
    connect(context->session(), &ControllerSession::requestFinished, this, &SetupPage::onResult);
    connect(context, &MachineContext::knownParametersChanged, this, &SetupPage::applyKnown);
    connect(context->session(), &ControllerSession::linkStateChanged, this, [this](LinkState st) {
        refreshButtons();
        // Where the protocol can read back, the form starts from the device's values, so
        // Write sends only what the technician changed; until then they are unknown.
        if (st == LinkState::Connected && m_anyReadable) {
            markReadableUnknown();
            read();
        }
    });
    rebuild();
}

void SetupPage::rebuild()
{
    m_schema = m_context->schema();
    const QList<Axis> axes = m_context->axes();
    m_driveChooser->setAxes(axes);
    m_driveChooser->setVisible(axes.size() > SetupDriveChooser::kColumns);
    buildForm();
}

void SetupPage::showDrives()
{
    // Other drives' columns replace these: what the technician typed and did not write would
    // be gone, so the page keeps its columns until it is written (or set back).
    for (ParameterField* f : std::as_const(m_fields)) {
        if (f->isExplicit() && f->isChanged()) {
            m_driveChooser->revert();
            setMessage(tr("Write or undo the changes of %1 before showing other drives.")
                           .arg(f->displayName()),
                       true);
            return;
        }
    }
    buildForm();
    // What was read of the drives now shown, as it was read; the rest unknown.
    showRead(m_context->readBackParameters());
}

void SetupPage::buildForm()
{
    delete m_content;
    m_fields.clear();
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* inner = new QWidget(scroll);
    auto* v = new QVBoxLayout(inner);
    for (const QString& group : m_schema.groups())
        v->addWidget(buildGroup(group));
    v->addStretch(1);
    scroll->setWidget(inner);
    m_content = scroll;
    m_groups->addWidget(scroll);

    bool anyReadable = false;
    for (const ParameterSpec& spec : m_schema.specs())
        anyReadable = anyReadable || spec.readable;
    m_anyReadable = anyReadable;
    m_read->setVisible(anyReadable);
    m_info->setText(
        anyReadable ? QString()
                    : tr("This controller cannot read parameters back: the fields show the "
                         "defaults (or a loaded file) until written. After every connect, reset "
                         "or power cycle nothing counts as written."));
    m_info->setVisible(!anyReadable);
    showWhetherAnythingIsSettable();
    if (anyReadable)
        markReadableUnknown(); // not read yet: never shown as defaults
    applyKnown();
}

void SetupPage::markReadableUnknown()
{
    for (ParameterField* f : std::as_const(m_fields)) {
        if (f->spec().readable && !f->isExplicit())
            f->setUnknown();
    }
    refreshButtons();
}

void SetupPage::applyKnown()
{
    const ParameterSet& known = m_context->knownParameters();
    for (ParameterField* f : std::as_const(m_fields)) {
        const ParameterValue v = known.value(f->spec().name);
        f->setBaseline(f->axis() ? v.perAxis.value(*f->axis()) : v.global);
        const QVariant held = f->baseline();
        if (!held.isValid() || f->isUnknown())
            continue; // nothing known, or a read failed since (only a read fills it)
        if (!f->isExplicit()) {
            // What the device holds, also where someone else wrote it (the machine file's
            // setup on every connect, issue 47 item 9): a field without a choice of the
            // technician's shows it. Kept at the schema's default it was marked as differing,
            // and Write all sent the defaults over the file's values.
            if (f->value() != held)
                f->setValue(held);
        } else if (!f->spec().readable && f->value() == held) {
            // A write-only choice that reached the device is no pending edit any more, so the
            // values written on the next connect replace it as well. (Readable fields keep
            // their mark: their values come from the page's reads of the device.)
            f->setValue(held);
        }
    }
    refreshButtons();
}

bool SetupPage::hasSettableParameters()
{
    for (const ParameterSpec& spec : m_schema.specs()) {
        if (spec.writable)
            return true;
    }
    setMessage(noParametersText(), true);
    return false;
}

QString SetupPage::noParametersText()
{
    return tr("This controller's protocol has no parameters to set: there is nothing to write, "
              "read, save or load here.");
}

void SetupPage::showWhetherAnythingIsSettable()
{
    // A protocol without parameters (laser motor axes) gets no empty form with buttons that
    // would do nothing (issue 16): it says why instead. (Before a model is chosen the page
    // stays as it is.)
    bool anyWritable = false;
    for (const ParameterSpec& spec : m_schema.specs())
        anyWritable = anyWritable || spec.writable;
    const bool none = !anyWritable && m_context->model();
    for (QPushButton* b : {m_write, m_writeAll})
        b->setVisible(!none);
    // Write & verify only where something can be read back (issue 31): on a write-only
    // controller (E-LAB, EMIS SMC-IC4) it would verify nothing, so Write is the only write.
    m_writeVerify->setVisible(!none && m_anyReadable);
    for (QPushButton* b : std::as_const(m_formButtons))
        b->setVisible(!none);
    if (none) {
        m_read->setVisible(false);
        m_info->setText(noParametersText());
    }
}

QWidget* SetupPage::buildGroup(const QString& group)
{
    // "Power & spindle": the '&' is text, not a keyboard mnemonic.
    auto* box = new QGroupBox(
        ParameterSchema::displayText(group).replace(QLatin1Char('&'), QStringLiteral("&&")));
    auto* grid = new QGridLayout(box);
    const QList<Axis> axes = m_driveChooser->shownAxes();
    bool anyPerAxis = false;
    for (const ParameterSpec& spec : m_schema.specs())
        anyPerAxis = anyPerAxis || (spec.group == group && spec.perAxis);
    if (anyPerAxis) {
        for (int i = 0; i < axes.size(); ++i) {
            auto* header = new QLabel(m_context->controllerAxisName(axes[i]), box);
            header->setAlignment(Qt::AlignCenter);
            QFont f = header->font();
            f.setBold(true);
            header->setFont(f);
            grid->addWidget(header, 0, 1 + i);
        }
    }
    int row = 1;
    for (const ParameterSpec& spec : m_schema.specs()) {
        if (spec.group != group)
            continue;
        auto* label = new QLabel(ParameterSchema::displayText(spec.label), box);
        label->setToolTip(ParameterSchema::displayText(spec.description));
        grid->addWidget(label, row, 0);
        auto add = [&](std::optional<Axis> axis, int column, int span) {
            auto* f = new ParameterField(m_schema, spec, axis, box);
            if (axis)
                f->setAxisName(m_context->controllerAxisName(*axis));
            connect(f, &ParameterField::edited, this, &SetupPage::refreshButtons);
            m_fields << f;
            grid->addWidget(f, row, column, 1, span);
        };
        if (spec.perAxis) {
            for (int i = 0; i < axes.size(); ++i)
                add(axes[i], 1 + i, 1);
        } else {
            add(std::nullopt, 1, qMax(1, int(axes.size())));
        }
        auto* unit = new QLabel(ParameterSchema::displayUnitColumn(spec), box);
        unit->setObjectName(QStringLiteral("unit-") + spec.name);
        unit->setToolTip(ParameterSchema::displayUnitToolTip(spec));
        grid->addWidget(unit, row, 1 + int(axes.size()));
        ++row;
    }
    grid->setColumnStretch(0, 2);
    for (int i = 0; i < axes.size(); ++i)
        grid->setColumnStretch(1 + i, 1);
    return box;
}

ParameterField* SetupPage::field(const QString& name, std::optional<Axis> axis) const
{
    for (ParameterField* f : m_fields) {
        if (f->spec().name == name && f->axis() == axis)
            return f;
    }
    return nullptr;
}

WritePreview* SetupPage::openPreview() const
{
    return m_preview.data();
}

QString SetupPage::messageText() const
{
    return m_message->fullText();
}

QString SetupPage::invalidText(const QStringList& errors)
{
    // One line (the page and the status bar show one line); every reason, none dropped.
    return tr("Invalid values cannot be written (%1): %2")
        .arg(errors.size())
        .arg(errors.join(QStringLiteral("; ")));
}

QStringList SetupPage::fieldErrors() const
{
    QStringList errors;
    for (ParameterField* f : m_fields) {
        const QString err = f->error(); // names the field by its translated label
        if (!err.isEmpty())
            errors << err;
    }
    return errors;
}

bool SetupPage::formValues(ParameterSet* set, QStringList* errors) const
{
    const QStringList errs = fieldErrors();
    if (errors)
        *errors = errs;
    if (!errs.isEmpty())
        return false;
    ParameterSet out;
    for (ParameterField* f : m_fields) {
        if (!f->spec().writable || !f->value().isValid())
            continue; // unknown values are not part of the form's values
        ParameterValue& v = out[f->spec().name];
        if (f->axis())
            v.perAxis.insert(*f->axis(), f->value());
        else
            v.global = f->value();
    }
    *set = out;
    return true;
}

ParameterSet SetupPage::changedValues() const
{
    if (!fieldErrors().isEmpty())
        return {};
    return WritePlan::build(m_fields, WritePlan::Scope::Changed).set;
}

void SetupPage::refreshButtons()
{
    const QStringList errors = fieldErrors();
    const bool connected = m_context->isConnected();
    const QString why = !errors.isEmpty() ? tr("Cannot write: %1").arg(errors.first())
                        : !connected      ? tr("Not connected")
                                          : QString();
    for (QPushButton* b : {m_write, m_writeVerify, m_writeAll}) {
        b->setEnabled(why.isEmpty());
        b->setToolTip(!why.isEmpty()    ? why
                      : b == m_writeAll ? tr("Write every value on the page to the controller")
                                        : tr("Write what is changed or not known to be on the "
                                             "controller"));
    }
    m_read->setEnabled(connected);
    if (!errors.isEmpty())
        setMessage(invalidText(errors), true, errors);
    else if (m_message->property("invalidShown").toBool())
        setMessage(QString(), false);
    m_message->setProperty("invalidShown", !errors.isEmpty());
}

bool SetupPage::write(bool verify, bool confirm)
{
    return writePlanned(int(WritePlan::Scope::Changed), verify, confirm);
}

bool SetupPage::writeAll(bool verify, bool confirm)
{
    return writePlanned(int(WritePlan::Scope::All), verify, confirm);
}

bool SetupPage::writePlanned(int scope, bool verify, bool confirm)
{
    if (!hasSettableParameters())
        return false;
    const QStringList errors = fieldErrors();
    if (!errors.isEmpty()) {
        setMessage(invalidText(errors), true, errors);
        return false;
    }
    const WritePlan plan = WritePlan::build(m_fields, WritePlan::Scope(scope));
    if (plan.set.isEmpty()) {
        setMessage(plan.nothingToWriteText(), false);
        return false;
    }
    return writeSet(plan.set, verify, confirm);
}

bool SetupPage::writeSet(const ParameterSet& set, bool verify, bool confirm)
{
    const QString invalid = m_schema.validate(set, m_context->axes());
    if (!invalid.isEmpty()) {
        setMessage(tr("Not written: %1").arg(invalid), true);
        return false;
    }
    // A multi-drive bus shows exactly what goes to which drive first; others ask only for
    // the schema's warnings.
    const bool preview =
        m_context->capabilities().multiDrive || !WriteWarnings::collect(m_schema, set).isEmpty();
    if (!confirm || !preview) {
        send(set, verify);
        return true;
    }
    auto* dialog =
        new WritePreview(m_schema, set, m_context->session()->spec().options.axisAddresses,
                         {m_context->readBackParameters(), m_context->knownParameters()},
                         m_context->session()->spec().options.axisNames, window());
    connect(dialog, &QDialog::finished, this, [this, set, verify](int result) {
        if (result == QDialog::Accepted)
            send(set, verify);
        else
            setMessage(tr("Not written: cancelled."), false);
    });
    dialogs::showForPart(dialog, this);
    m_preview = dialog;
    return true;
}

void SetupPage::send(const ParameterSet& set, bool verify)
{
    m_pendingSet = set;
    m_pendingVerify = verify;
    m_pendingWrite = m_context->writeParameters(set, verify);
    setMessage(verify && WriteResultText::anyVerifiable(m_schema, set)
                   ? tr("Writing and verifying %n parameter(s)\u2026", nullptr, int(set.size()))
                   : tr("Writing %n parameter(s)\u2026", nullptr, int(set.size())),
               false);
}

void SetupPage::read()
{
    QStringList names;
    for (const ParameterSpec& spec : m_schema.specs()) {
        if (spec.readable)
            names << spec.name;
    }
    if (names.isEmpty()) {
        setMessage(tr("This controller cannot read parameters back."), true);
        return;
    }
    m_pendingRead = m_context->readParameters(names);
    setMessage(tr("Reading\u2026"), false);
}

void SetupPage::onResult(const CommandResult& result)
{
    if (result.id == m_pendingWrite && m_pendingWrite != 0) {
        m_pendingWrite = 0;
        if (result.ok()) {
            // The context now knows the values (its baselines follow, applyKnown()).
            setMessage(WriteResultText::success(m_schema, m_pendingSet, m_pendingVerify,
                                                m_context->session()->spec().options.axisNames),
                       false);
        } else {
            setMessage(tr("Write failed: %1").arg(result.message), true);
        }
    } else if (result.id == m_pendingRead && m_pendingRead != 0) {
        m_pendingRead = 0;
        // A failed read may still carry what could be read (some drives answered).
        const ParameterSet set = result.value.canConvert<ParameterSet>()
                                     ? result.value.value<ParameterSet>()
                                     : ParameterSet{};
        showRead(set);
        if (result.ok())
            setMessage(tr("Read %n parameter(s).", nullptr, int(set.size())), false);
        else
            setMessage(tr("Read failed: %1. Values that could not be read are shown as "
                          "unknown; they are written only if you set them.")
                           .arg(result.message),
                       true);
    }
}

void SetupPage::showRead(const ParameterSet& set)
{
    for (ParameterField* f : std::as_const(m_fields)) {
        if (!f->spec().readable)
            continue;
        const ParameterValue v = set.value(f->spec().name);
        const QVariant value = f->axis() ? v.perAxis.value(*f->axis()) : v.global;
        if (value.isValid())
            f->setValue(value);
        else if (!f->isExplicit())
            f->setUnknown(); // never a default in place of a value that could not be read
    }
    refreshButtons();
}

void SetupPage::applyToForm(const ParameterSet& set)
{
    for (ParameterField* f : m_fields) {
        if (!set.contains(f->spec().name))
            continue;
        const ParameterValue& v = set.value(f->spec().name);
        f->setValue(f->axis() ? v.perAxis.value(*f->axis()) : v.global, true);
    }
    refreshButtons();
}

void SetupPage::resetToDefaults()
{
    for (ParameterField* f : m_fields)
        f->setValue(f->spec().defaultValue, true);
    refreshButtons();
}

void SetupPage::setMessage(const QString& text, bool error, const QStringList& details)
{
    m_message->setMessage(text, details);
    m_message->setStyleSheet(error ? QStringLiteral("QLabel { color: #c62828; }") : QString());
    if (!text.isEmpty())
        Q_EMIT message(text);
}

} // namespace stepdeck::ui
