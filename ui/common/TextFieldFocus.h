#pragma once

namespace stepdeck::ui {

// A widget that takes typed text has the keyboard focus (a line edit, a spin box, a plain or
// rich text edit, an editable combo box): keys are the text's then. The keyboard jog pauses
// (KeyboardJog) and the shortcuts that move the machine do not fire (MachineShortcutGuard,
// issue 47 item 6); STOP and PANIC always do.
bool textFieldHasFocus();

} // namespace stepdeck::ui
