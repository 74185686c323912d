<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
    <context>
        <name>stepdeck::emis::EmisController</name>
        <message numerus="yes">
            <source> (%n command(s) before it were accepted)</source>
            <translation>
                <numerusform> (%n command before it was accepted)</numerusform>
                <numerusform> (%n commands before it were accepted)</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::emis::ReplyDecoder</name>
        <message numerus="yes">
            <source>%n byte(s) that are neither text nor a reply terminator</source>
            <translation>
                <numerusform>%n byte that is neither text nor a reply terminator</numerusform>
                <numerusform>%n bytes that are neither text nor a reply terminator</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::machine::MachineSetup</name>
        <message numerus="yes">
            <source>controller "%1": wrote its setup from %2 (%n parameter(s))</source>
            <translation>
                <numerusform>controller "%1": wrote its setup from %2 (%n parameter)</numerusform>
                <numerusform>controller "%1": wrote its setup from %2 (%n parameters)</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramCheck</name>
        <message numerus="yes">
            <source>tool lengths by touch-off (the machine file's toolLength): the run holds at %n tool change(s) (M6, line(s) %1) until the work Z is set for the new tool; G43 adds no length</source>
            <translation>
                <numerusform>tool lengths by touch-off (the machine file's toolLength): the run holds at %n tool change (M6, line %1) until the work Z is set for the new tool; G43 adds no length</numerusform>
                <numerusform>tool lengths by touch-off (the machine file's toolLength): the run holds at %n tool changes (M6, lines %1) until the work Z is set for the new tool; G43 adds no length</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%1 (also on %n more line(s))</source>
            <translation>
                <numerusform>%1 (also on %n more line)</numerusform>
                <numerusform>%1 (also on %n more lines)</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramParser</name>
        <message numerus="yes">
            <source>%n line(s) after the program's end are not read, as in LinuxCNC (nothing after M2, M30 or the closing "%" runs)</source>
            <translation>
                <numerusform>%n line after the program's end is not read, as in LinuxCNC (nothing after M2, M30 or the closing "%" runs)</numerusform>
                <numerusform>%n lines after the program's end are not read, as in LinuxCNC (nothing after M2, M30 or the closing "%" runs)</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>block delete is on: %n line(s) starting with "/" are skipped, this one the first (switch it off to run them)</source>
            <translation>
                <numerusform>block delete is on: %n line starting with "/" is skipped, this one (switch it off to run it)</numerusform>
                <numerusform>block delete is on: %n lines starting with "/" are skipped, this one the first (switch it off to run them)</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%1 on %n arc(s), this one the first: an offset along the plane's normal that is 0 is left out, as GRBL does (LinuxCNC refuses it; any other value is refused)</source>
            <translation>
                <numerusform>%1 on %n arc, this one: an offset along the plane's normal that is 0 is left out, as GRBL does (LinuxCNC refuses it; any other value is refused)</numerusform>
                <numerusform>%1 on %n arcs, this one the first: an offset along the plane's normal that is 0 is left out, as GRBL does (LinuxCNC refuses it; any other value is refused)</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::DiffDialog</name>
        <message numerus="yes">
            <source>%1 changes %n value(s) (highlighted).</source>
            <translation>
                <numerusform>%1 changes %n value (highlighted).</numerusform>
                <numerusform>%1 changes %n values (highlighted).</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::DrivePanel</name>
        <message numerus="yes">
            <source>%n drive(s) found</source>
            <translation>
                <numerusform>%n drive found</numerusform>
                <numerusform>%n drives found</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Scan cancelled after address %1: %n drive(s) found</source>
            <translation>
                <numerusform>Scan cancelled after address %1: %n drive found</numerusform>
                <numerusform>Scan cancelled after address %1: %n drives found</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramErrorList</name>
        <message numerus="yes">
            <source>%n error(s); click one to go to its line.</source>
            <translation>
                <numerusform>%n error; click it to go to its line.</numerusform>
                <numerusform>%n errors; click one to go to its line.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Line %1 is not in the editor, which shows the first %n line(s) of this large file.</source>
            <translation>
                <numerusform>Line %1 is not in the editor, which shows the first line of this large file.</numerusform>
                <numerusform>Line %1 is not in the editor, which shows the first %n lines of this large file.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramPage</name>
        <message numerus="yes">
            <source>%n error(s); line %1: %2</source>
            <translation>
                <numerusform>%n error; line %1: %2</numerusform>
                <numerusform>%n errors; line %1: %2</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Finished: %n block(s) run.</source>
            <translation>
                <numerusform>Finished: %n block run.</numerusform>
                <numerusform>Finished: %n blocks run.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Checked against the machine: no errors; %n note(s), line %1: %2</source>
            <translation>
                <numerusform>Checked against the machine: no errors; %n note, line %1: %2</numerusform>
                <numerusform>Checked against the machine: no errors; %n notes, line %1: %2</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramPreviewView</name>
        <message numerus="yes">
            <source>%n line(s)</source>
            <translation>
                <numerusform>%n line</numerusform>
                <numerusform>%n lines</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n block(s) run</source>
            <translation>
                <numerusform>%n block run</numerusform>
                <numerusform>%n blocks run</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::RecordsPage</name>
        <message numerus="yes">
            <source>%n record(s) read.</source>
            <translation>
                <numerusform>%n record read.</numerusform>
                <numerusform>%n records read.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::SetupPage</name>
        <message numerus="yes">
            <source>Writing and verifying %n parameter(s)…</source>
            <translation>
                <numerusform>Writing and verifying %n parameter…</numerusform>
                <numerusform>Writing and verifying %n parameters…</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Writing %n parameter(s)…</source>
            <translation>
                <numerusform>Writing %n parameter…</numerusform>
                <numerusform>Writing %n parameters…</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Read %n parameter(s).</source>
            <translation>
                <numerusform>Read %n parameter.</numerusform>
                <numerusform>Read %n parameters.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::TrafficConsole</name>
        <message numerus="yes">
            <source>%n record(s)</source>
            <translation>
                <numerusform>%n record</numerusform>
                <numerusform>%n records</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::WritePlan</name>
        <message numerus="yes">
            <source>Nothing to write: %n value(s) could not be read (%1); they are written only once you set them.</source>
            <translation>
                <numerusform>Nothing to write: %n value could not be read (%1); it is written only once you set it.</numerusform>
                <numerusform>Nothing to write: %n values could not be read (%1); they are written only once you set them.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::WritePreview</name>
        <message numerus="yes">
            <source>These %n value(s) will be sent, and nothing else:</source>
            <translation>
                <numerusform>This %n value will be sent, and nothing else:</numerusform>
                <numerusform>These %n values will be sent, and nothing else:</numerusform>
            </translation>
        </message>
    </context>
</TS>
