<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
    <context>
        <name>LaserAnswerPolicy</name>
        <message>
            <source>it may still be moving</source>
            <translation>sie fährt womöglich noch</translation>
        </message>
        <message>
            <source>its position is unknown</source>
            <translation>ihre Position ist unbekannt</translation>
        </message>
        <message>
            <source>its position (%1 steps, %2 laser units) is outside the laser's range 0..%3</source>
            <translation>ihre Position (%1 Schritte, %2 Lasereinheiten) liegt außerhalb des Laserbereichs 0..%3</translation>
        </message>
        <message>
            <source>%1, but %2</source>
            <translation>%1, aber %2</translation>
        </message>
        <message>
            <source>axis %1 is referenced</source>
            <translation>Achse %1 ist referenziert</translation>
        </message>
        <message>
            <source>axis %1 stopped at a limit switch before it was referenced</source>
            <translation>Achse %1 hat vor dem Referenzieren an einem Endschalter angehalten</translation>
        </message>
        <message>
            <source>axis %1 stopped before it was referenced</source>
            <translation>Achse %1 hat vor dem Referenzieren angehalten</translation>
        </message>
        <message>
            <source>axis %1 stopped at a limit switch</source>
            <translation>Achse %1 hat an einem Endschalter angehalten</translation>
        </message>
        <message>
            <source>axis %1 did not confirm reaching its target %2 steps: %3</source>
            <translation>Achse %1 hat das Erreichen ihres Ziels %2 Schritte nicht bestätigt: %3</translation>
        </message>
        <message>
            <source>axis %1 stopped at %2 steps, short of its target %3 (stopped by the operator?)</source>
            <translation>Achse %1 hat bei %2 Schritten vor ihrem Ziel %3 angehalten (vom Bediener gestoppt?)</translation>
        </message>
        <message>
            <source>axis %1 stands at an active limit switch</source>
            <translation>Achse %1 steht an einem aktiven Endschalter</translation>
        </message>
        <message>
            <source>the door opened (axis %1)</source>
            <translation>die Tür wurde geöffnet (Achse %1)</translation>
        </message>
        <message>
            <source>the door closed (axis %1)</source>
            <translation>die Tür wurde geschlossen (Achse %1)</translation>
        </message>
    </context>
    <context>
        <name>LaserBridgeConfig</name>
        <message>
            <source>--map expects LASER_AXIS=AXIS pairs such as 1=X,2=Y,3=Z, got '%1'</source>
            <translation>--map erwartet Paare LASERACHSE=ACHSE wie 1=X,2=Y,3=Z, nicht '%1'</translation>
        </message>
        <message>
            <source>--map: '%1=%2' is not LASER_AXIS=AXIS (laser axes 1, 2, 3; axes X, Y, Z, U)</source>
            <translation>--map: '%1=%2' ist nicht LASERACHSE=ACHSE (Laserachsen 1, 2, 3; Achsen X, Y, Z, U)</translation>
        </message>
        <message>
            <source>--map: laser axis %1 is mapped twice</source>
            <translation>--map: Laserachse %1 ist zweimal zugeordnet</translation>
        </message>
        <message>
            <source>--scale expects steps per laser unit, a number above 0 and at most %1, got '%2'</source>
            <translation>--scale erwartet Schritte pro Lasereinheit, eine Zahl über 0 und höchstens %1, nicht '%2'</translation>
        </message>
        <message>
            <source>--home expects AXIS=-1 or AXIS=1 per axis, e.g. X=-1,Y=-1,Z=1, got '%1'</source>
            <translation>--home erwartet ACHSE=-1 oder ACHSE=1 je Achse, z. B. X=-1,Y=-1,Z=1, nicht '%1'</translation>
        </message>
        <message>
            <source>--door-input expects an input number from 1 to 64, got '%1'</source>
            <translation>--door-input erwartet eine Eingangsnummer von 1 bis 64, nicht '%1'</translation>
        </message>
        <message>
            <source>the axis map is empty: map at least one laser axis</source>
            <translation>die Achszuordnung ist leer: mindestens eine Laserachse zuordnen</translation>
        </message>
        <message>
            <source>the controller has no axis %1 (laser axis %2)</source>
            <translation>die Steuerung hat keine Achse %1 (Laserachse %2)</translation>
        </message>
        <message>
            <source>axis %1 is mapped to two laser axes</source>
            <translation>Achse %1 ist zwei Laserachsen zugeordnet</translation>
        </message>
        <message>
            <source>--home names axis %1, which no laser axis is mapped to</source>
            <translation>--home nennt Achse %1, der keine Laserachse zugeordnet ist</translation>
        </message>
        <message>
            <source>the scale must be above 0 and at most %1 steps per laser unit</source>
            <translation>der Maßstab muss über 0 und höchstens %1 Schritte pro Lasereinheit betragen</translation>
        </message>
        <message>
            <source>--home: this controller chooses the direction of its reference runs itself; leave --home out</source>
            <translation>--home: diese Steuerung wählt die Richtung ihrer Referenzfahrten selbst; --home weglassen</translation>
        </message>
    </context>
    <context>
        <name>Models</name>
        <message>
            <source>E-LAB 3-axis stepper controller</source>
            <translation>E-LAB 3-Achsen-Schrittmotorsteuerung</translation>
        </message>
        <message>
            <source>Laser marker motor axes (RS232)</source>
            <translation>Motorachsen eines Markierlasers (RS232)</translation>
        </message>
        <message>
            <source>EMIS SMC-IC4 4-axis controller</source>
            <translation>EMIS SMC-IC4 4-Achsen-Steuerung</translation>
        </message>
        <message>
            <source>Nanotec SMCI33 / SMCI47-S (RS485 bus)</source>
            <translation>Nanotec SMCI33 / SMCI47-S (RS485-Bus)</translation>
        </message>
    </context>
    <context>
        <name>NgcStructure</name>
        <message>
            <source>the O word's name is not closed by "&gt;"</source>
            <translation>der Name des O-Worts wird nicht durch „&gt;“ geschlossen</translation>
        </message>
        <message>
            <source>O needs a number or a &lt;name&gt;</source>
            <translation>O braucht eine Nummer oder einen &lt;name&gt;</translation>
        </message>
        <message>
            <source>O%1 needs a keyword: sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, break, continue, repeat or endrepeat</source>
            <translation>O%1 braucht ein Schlüsselwort: sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, break, continue, repeat oder endrepeat</translation>
        </message>
        <message>
            <source>"%1" is not an O-word keyword</source>
            <translation>„%1“ ist kein O-Wort-Schlüsselwort</translation>
        </message>
    </context>
    <context>
        <name>Parameters</name>
        <message>
            <source>steps/s</source>
            <translation>Schritte/s</translation>
        </message>
        <message>
            <source>Start speed</source>
            <translation>Startgeschwindigkeit</translation>
        </message>
        <message>
            <source>Speeds</source>
            <translation>Geschwindigkeiten</translation>
        </message>
        <message>
            <source>Step rate at the start of a ramp (SetStartSpeed, &lt;ESC&gt;S)</source>
            <translation>Schrittrate am Beginn einer Rampe (SetStartSpeed, &lt;ESC&gt;S)</translation>
        </message>
        <message>
            <source>Max speed</source>
            <translation>Maximalgeschwindigkeit</translation>
        </message>
        <message>
            <source>Plateau step rate of positioning and reference moves (SetMaxSpeed, &lt;ESC&gt;M)</source>
            <translation>Schrittrate im Plateau von Positionier- und Referenzfahrten (SetMaxSpeed, &lt;ESC&gt;M)</translation>
        </message>
        <message>
            <source>Feed speed</source>
            <translation>Vorschubgeschwindigkeit</translation>
        </message>
        <message>
            <source>Step rate in feed mode; must be below the start speed, feed has no ramp (SetFeedSpeed, &lt;FS&gt;)</source>
            <translation>Schrittrate im Vorschubbetrieb; muss unter der Startgeschwindigkeit liegen, der Vorschub hat keine Rampe (SetFeedSpeed, &lt;FS&gt;)</translation>
        </message>
        <message>
            <source>Acceleration</source>
            <translation>Beschleunigung</translation>
        </message>
        <message>
            <source>Ramp steepness of positioning moves; sensible values are 500 to 2000 (SetAcceleration, &lt;ESC&gt;A)</source>
            <translation>Rampensteilheit von Positionierfahrten; sinnvoll sind 500 bis 2000 (SetAcceleration, &lt;ESC&gt;A)</translation>
        </message>
        <message>
            <source>Switch polarity</source>
            <translation>Schalterpolarität</translation>
        </message>
        <message>
            <source>high</source>
            <translation>High-aktiv</translation>
        </message>
        <message>
            <source>low</source>
            <translation>Low-aktiv</translation>
        </message>
        <message>
            <source>Limit switch polarity</source>
            <translation>Polarität der Endschalter</translation>
        </message>
        <message>
            <source>Active level of the limit switches (SetSwitchPolarity, &lt;SO&gt;)</source>
            <translation>Aktiver Pegel der Endschalter (SetSwitchPolarity, &lt;SO&gt;)</translation>
        </message>
        <message>
            <source>Reference switch polarity</source>
            <translation>Polarität der Referenzschalter</translation>
        </message>
        <message>
            <source>Active level of the reference switches (SetSwitchPolarity, &lt;DLE&gt;)</source>
            <translation>Aktiver Pegel der Referenzschalter (SetSwitchPolarity, &lt;DLE&gt;)</translation>
        </message>
        <message>
            <source>Drive power</source>
            <translation>Motorstrom</translation>
        </message>
        <message>
            <source>Power &amp; spindle</source>
            <translation>Leistung &amp; Spindel</translation>
        </message>
        <message>
            <source>%</source>
            <translation>%</translation>
        </message>
        <message>
            <source>Motor current for all axes; the board maps it to off (&lt;25), 33 % (&lt;50), 66 % (&lt;75), 100 % (SetDrivePower, &lt;STX&gt;)</source>
            <translation>Motorstrom aller Achsen; die Platine setzt ihn auf aus (&lt;25), 33 % (&lt;50), 66 % (&lt;75), 100 % (SetDrivePower, &lt;STX&gt;)</translation>
        </message>
        <message>
            <source>Spindle speed</source>
            <translation>Spindeldrehzahl</translation>
        </message>
        <message>
            <source>rpm</source>
            <translation>U/min</translation>
        </message>
        <message>
            <source>0 switches the spindle relay off, anything above switches it on (SetSpindleRPM, &lt;SOH&gt;)</source>
            <translation>0 schaltet das Spindelrelais aus, jeder größere Wert ein (SetSpindleRPM, &lt;SOH&gt;)</translation>
        </message>
        <message>
            <source>Coolant</source>
            <translation>Kühlmittel</translation>
        </message>
        <message>
            <source>Coolant pump relay RS2 (SetCoolOnOff, &lt;SI&gt;)</source>
            <translation>Relais RS2 der Kühlmittelpumpe (SetCoolOnOff, &lt;SI&gt;)</translation>
        </message>
        <message>
            <source>Motor</source>
            <translation>Motor</translation>
        </message>
        <message>
            <source>Phase current</source>
            <translation>Phasenstrom</translation>
        </message>
        <message>
            <source>Motor current relative to the drive's full scale; values above 100 should be avoided (5.1)</source>
            <translation>Motorstrom bezogen auf den Vollausschlag der Steuerung; Werte über 100 sollten vermieden werden (5.1)</translation>
        </message>
        <message>
            <source>Idle current</source>
            <translation>Ruhestrom</translation>
        </message>
        <message>
            <source>Current at standstill, relative to full scale (not to the phase current); values above 100 should be avoided (5.2)</source>
            <translation>Strom im Stillstand, bezogen auf den Vollausschlag (nicht auf den Phasenstrom); Werte über 100 sollten vermieden werden (5.2)</translation>
        </message>
        <message>
            <source>Step mode</source>
            <translation>Schrittweite</translation>
        </message>
        <message>
            <source>adaptive</source>
            <translation>adaptiv</translation>
        </message>
        <message>
            <source>Microsteps per full step; 'adaptive' selects the adaptive step mode (5.3)</source>
            <translation>Mikroschritte je Vollschritt; 'adaptive' wählt die adaptive Schrittweite (5.3)</translation>
        </message>
        <message>
            <source>Step angle</source>
            <translation>Schrittwinkel</translation>
        </message>
        <message>
            <source>deg</source>
            <translation>°</translation>
        </message>
        <message>
            <source>Full-step angle of the motor in degrees, needed to convert encoder positions; changes cl-motor-pole-pairs as well (5.8, 8.6)</source>
            <translation>Vollschrittwinkel des Motors in Grad, nötig zur Umrechnung der Encoderpositionen; ändert auch cl-motor-pole-pairs (5.8, 8.6)</translation>
        </message>
        <message>
            <source>Motor mode</source>
            <translation>Motormodus</translation>
        </message>
        <message>
            <source>positioning</source>
            <translation>Positionierung</translation>
        </message>
        <message>
            <source>speed</source>
            <translation>Drehzahl</translation>
        </message>
        <message>
            <source>flag-positioning</source>
            <translation>Flag-Positionierung</translation>
        </message>
        <message>
            <source>clock-direction</source>
            <translation>Takt-Richtung</translation>
        </message>
        <message>
            <source>analog</source>
            <translation>analog</translation>
        </message>
        <message>
            <source>joystick</source>
            <translation>Joystick</translation>
        </message>
        <message>
            <source>Motor address</source>
            <translation>Motoradresse</translation>
        </message>
        <message>
            <source>RS485 bus address of the drive (5.4)</source>
            <translation>RS485-Busadresse der Steuerung (5.4)</translation>
        </message>
        <message>
            <source>Communication continues at the new address. It must not be used by another drive on the bus, or no communication is possible any more (manual 5.4).</source>
            <translation>Die Kommunikation läuft unter der neuen Adresse weiter. Sie darf von keiner anderen Steuerung am Bus benutzt werden, sonst ist keine Kommunikation mehr möglich (Handbuch 5.4).</translation>
        </message>
        <message>
            <source>Backlash</source>
            <translation>Umkehrspiel</translation>
        </message>
        <message>
            <source>steps</source>
            <translation>Schritte</translation>
        </message>
        <message>
            <source>Steps made on a direction change before the position counts, to take up gear play (5.33)</source>
            <translation>Schritte bei einem Richtungswechsel, bevor die Position zählt, um Getriebespiel auszugleichen (5.33)</translation>
        </message>
        <message>
            <source>Send status after moves</source>
            <translation>Status nach Fahrten senden</translation>
        </message>
        <message>
            <source>Ramp shape</source>
            <translation>Rampenform</translation>
        </message>
        <message>
            <source>trapezoid</source>
            <translation>Trapez</translation>
        </message>
        <message>
            <source>sinus</source>
            <translation>Sinus</translation>
        </message>
        <message>
            <source>Ramp of the positioning mode (5.34)</source>
            <translation>Rampe des Positioniermodus (5.34)</translation>
        </message>
        <message>
            <source>Brake</source>
            <translation>Bremse</translation>
        </message>
        <message>
            <source>Brake release delay</source>
            <translation>Verzögerung Bremse lösen</translation>
        </message>
        <message>
            <source>ms</source>
            <translation>ms</translation>
        </message>
        <message>
            <source>Wait between switching the motor current on and releasing the brake (5.35)</source>
            <translation>Wartezeit zwischen Einschalten des Motorstroms und Lösen der Bremse (5.35)</translation>
        </message>
        <message>
            <source>Motion delay after brake release</source>
            <translation>Bewegungsverzögerung nach Lösen der Bremse</translation>
        </message>
        <message>
            <source>Wait between releasing the brake and allowing motion (5.36)</source>
            <translation>Wartezeit zwischen Lösen der Bremse und Freigabe der Bewegung (5.36)</translation>
        </message>
        <message>
            <source>Current-off delay after braking</source>
            <translation>Verzögerung Strom aus nach dem Bremsen</translation>
        </message>
        <message>
            <source>Wait between engaging the brake and switching the motor current off (5.37)</source>
            <translation>Wartezeit zwischen Schließen der Bremse und Abschalten des Motorstroms (5.37)</translation>
        </message>
        <message>
            <source>Limit switches</source>
            <translation>Endschalter</translation>
        </message>
        <message>
            <source>External limit switch type</source>
            <translation>Typ des externen Endschalters</translation>
        </message>
        <message>
            <source>normally-closed</source>
            <translation>Öffner</translation>
        </message>
        <message>
            <source>normally-open</source>
            <translation>Schließer</translation>
        </message>
        <message>
            <source>Switch between +5 V and input 6: a normally closed switch ('Oeffner') reads high until it is actuated (5.7)</source>
            <translation>Schalter zwischen +5 V und Eingang 6: ein Öffner liest high, bis er betätigt wird (5.7)</translation>
        </message>
        <message>
            <source>Internal switch, reference run</source>
            <translation>Interner Schalter, Referenzfahrt</translation>
        </message>
        <message>
            <source>free-forward</source>
            <translation>vorwärts freifahren</translation>
        </message>
        <message>
            <source>free-backward</source>
            <translation>rückwärts freifahren</translation>
        </message>
        <message>
            <source>Free travel after the encoder index in an internal reference run, relative to the run: backward leaves the mark again (5.6 bits 0-1)</source>
            <translation>Freifahren nach dem Encoder-Index bei einer internen Referenzfahrt, bezogen auf die Fahrt: rückwärts verlässt die Marke wieder (5.6 Bits 0-1)</translation>
        </message>
        <message>
            <source>Internal switch, normal run</source>
            <translation>Interner Schalter, normale Fahrt</translation>
        </message>
        <message>
            <source>stop</source>
            <translation>Stopp</translation>
        </message>
        <message>
            <source>ignore</source>
            <translation>ignorieren</translation>
        </message>
        <message>
            <source>What the drive does when it reaches the encoder index during a normal run; useful when the motor must not turn more than one revolution (5.6 bits 2-5)</source>
            <translation>Verhalten der Steuerung, wenn sie während einer normalen Fahrt den Encoder-Index erreicht; nützlich, wenn der Motor nicht mehr als eine Umdrehung machen darf (5.6 Bits 2-5)</translation>
        </message>
        <message>
            <source>External switch, reference run</source>
            <translation>Externer Schalter, Referenzfahrt</translation>
        </message>
        <message>
            <source>Free travel after reaching the external switch in an external reference run, relative to the run: backward backs off the switch (5.6 bits 9-10)</source>
            <translation>Freifahren nach Erreichen des externen Schalters bei einer externen Referenzfahrt, bezogen auf die Fahrt: rückwärts fährt vom Schalter weg (5.6 Bits 9-10)</translation>
        </message>
        <message>
            <source>External switch, normal run</source>
            <translation>Externer Schalter, normale Fahrt</translation>
        </message>
        <message>
            <source>What the drive does when it reaches the external switch during a normal run; 'stop' limits the travel hard (5.6 bits 11-14)</source>
            <translation>Verhalten der Steuerung, wenn sie während einer normalen Fahrt den externen Schalter erreicht; 'stop' begrenzt den Weg hart (5.6 Bits 11-14)</translation>
        </message>
        <message>
            <source>Encoder &amp; error correction</source>
            <translation>Encoder &amp; Fehlerkorrektur</translation>
        </message>
        <message>
            <source>Error correction</source>
            <translation>Fehlerkorrektur</translation>
        </message>
        <message>
            <source>off</source>
            <translation>aus</translation>
        </message>
        <message>
            <source>after-move</source>
            <translation>nach der Fahrt</translation>
        </message>
        <message>
            <source>during-move</source>
            <translation>während der Fahrt</translation>
        </message>
        <message>
            <source>Position check by the encoder. Must be 'off' for motors without an encoder, or the drive keeps correcting. 'during-move' is not implemented by the firmware (5.9)</source>
            <translation>Positionsprüfung durch den Encoder. Muss bei Motoren ohne Encoder 'off' sein, sonst korrigiert die Steuerung ständig. 'during-move' ist in der Firmware nicht implementiert (5.9)</translation>
        </message>
        <message>
            <source>Correction record</source>
            <translation>Korrektursatz</translation>
        </message>
        <message>
            <source>Record used for the correction run (5.10)</source>
            <translation>Für die Korrekturfahrt benutzter Satz (5.10)</translation>
        </message>
        <message>
            <source>Encoder direction</source>
            <translation>Encoderrichtung</translation>
        </message>
        <message>
            <source>normal</source>
            <translation>normal</translation>
        </message>
        <message>
            <source>reversed</source>
            <translation>umgekehrt</translation>
        </message>
        <message>
            <source>Reverses the counting direction of the encoder (5.11)</source>
            <translation>Kehrt die Zählrichtung des Encoders um (5.11)</translation>
        </message>
        <message>
            <source>Settle time</source>
            <translation>Einschwingzeit</translation>
        </message>
        <message>
            <source>x10 ms</source>
            <translation>x10 ms</translation>
        </message>
        <message>
            <source>Wait between the end of a run and the encoder check; the drive reports ready only after it (5.12)</source>
            <translation>Wartezeit zwischen Fahrtende und Encoderprüfung; die Steuerung meldet erst danach bereit (5.12)</translation>
        </message>
        <message>
            <source>Max encoder deviation</source>
            <translation>Maximale Encoderabweichung</translation>
        </message>
        <message>
            <source>Allowed difference between demand and encoder position; must be above 0 for step modes finer than 1/10 (1.8 deg) or 1/5 (0.9 deg) (5.13)</source>
            <translation>Erlaubte Differenz zwischen Soll- und Encoderposition; muss bei Schrittweiten feiner als 1/10 (1,8°) bzw. 1/5 (0,9°) über 0 liegen (5.13)</translation>
        </message>
        <message>
            <source>Inputs &amp; outputs</source>
            <translation>Ein- &amp; Ausgänge</translation>
        </message>
        <message>
            <source>I/O used by firmware</source>
            <translation>Von der Firmware benutzte E/A</translation>
        </message>
        <message>
            <source>bitmask</source>
            <translation>Bitmaske</translation>
        </message>
        <message>
            <source>Bit set: the firmware uses the I/O; clear: free for the user. Bits 0-5 inputs 1-6, 16-17 outputs 1-2. All bits are written at once (5.24)</source>
            <translation>Bit gesetzt: die Firmware benutzt den Ein-/Ausgang; gelöscht: frei für den Anwender. Bits 0-5 Eingänge 1-6, 16-17 Ausgänge 1-2. Alle Bits werden auf einmal geschrieben (5.24)</translation>
        </message>
        <message>
            <source>I/O polarity</source>
            <translation>E/A-Polarität</translation>
        </message>
        <message>
            <source>Bit set: normal polarity, clear: inverted. Bits 0-5 inputs 1-6, 16-17 outputs 1-2 (5.25)</source>
            <translation>Bit gesetzt: normale Polarität, gelöscht: invertiert. Bits 0-5 Eingänge 1-6, 16-17 Ausgänge 1-2 (5.25)</translation>
        </message>
        <message>
            <source>Input interrupts</source>
            <translation>Eingangs-Interrupts</translation>
        </message>
        <message>
            <source>Interrupt on every edge of inputs 1-6 (bits 0-5); input 6 reacts to one edge only (5.26)</source>
            <translation>Interrupt bei jeder Flanke der Eingänge 1-6 (Bits 0-5); Eingang 6 reagiert nur auf eine Flanke (5.26)</translation>
        </message>
        <message>
            <source>Interrupts on rising edge</source>
            <translation>Interrupts bei steigender Flanke</translation>
        </message>
        <message>
            <source>Inputs (bits 0-5) whose interrupt reacts to rising edges (5.27)</source>
            <translation>Eingänge (Bits 0-5), deren Interrupt auf steigende Flanken reagiert (5.27)</translation>
        </message>
        <message>
            <source>Interrupts on falling edge</source>
            <translation>Interrupts bei fallender Flanke</translation>
        </message>
        <message>
            <source>Inputs (bits 0-5) whose interrupt reacts to falling edges (5.28)</source>
            <translation>Eingänge (Bits 0-5), deren Interrupt auf fallende Flanken reagiert (5.28)</translation>
        </message>
        <message>
            <source>Debounce time</source>
            <translation>Entprellzeit</translation>
        </message>
        <message>
            <source>Wait after an input change until the signal counts as stable (5.29)</source>
            <translation>Wartezeit nach einer Eingangsänderung, bis das Signal als stabil gilt (5.29)</translation>
        </message>
        <message>
            <source>Outputs</source>
            <translation>Ausgänge</translation>
        </message>
        <message>
            <source>Output 1 = bit 16 (65536), output 2 = bit 17 (131072); only outputs freed with io-mask follow (5.30)</source>
            <translation>Ausgang 1 = Bit 16 (65536), Ausgang 2 = Bit 17 (131072); nur mit io-mask freigegebene Ausgänge folgen (5.30)</translation>
        </message>
        <message>
            <source>Input states</source>
            <translation>Eingangszustände</translation>
        </message>
        <message>
            <source>Inputs 1-6 (bits 0-5); bit 6 is 0 while the encoder is at its index mark (read with ZY, 5.30)</source>
            <translation>Eingänge 1-6 (Bits 0-5); Bit 6 ist 0, solange der Encoder auf seiner Indexmarke steht (gelesen mit ZY, 5.30)</translation>
        </message>
        <message>
            <source>Record</source>
            <translation>Satz</translation>
        </message>
        <message>
            <source>Positioning mode</source>
            <translation>Positionierart</translation>
        </message>
        <message>
            <source>Meaning depends on the motor mode (6.6). Positioning: 1 relative, 2 absolute, 3 internal reference run, 4 external reference run. Speed: 1 speed mode; 2 is not used there and is ignored.</source>
            <translation>Die Bedeutung hängt vom Motormodus ab (6.6). Positionierung: 1 relativ, 2 absolut, 3 interne Referenzfahrt, 4 externe Referenzfahrt. Drehzahl: 1 Drehzahlmodus; 2 wird dort nicht benutzt und ignoriert.</translation>
        </message>
        <message>
            <source>Travel distance</source>
            <translation>Verfahrweg</translation>
        </message>
        <message>
            <source>Relative: distance (positive, direction from 'direction'); absolute: target position. Full steps in adaptive mode (6.7)</source>
            <translation>Relativ: Weg (positiv, Richtung aus 'direction'); absolut: Zielposition. Vollschritte im adaptiven Modus (6.7)</translation>
        </message>
        <message>
            <source>Minimum frequency</source>
            <translation>Minimalfrequenz</translation>
        </message>
        <message>
            <source>Hz</source>
            <translation>Hz</translation>
        </message>
        <message>
            <source>Start speed of a run in steps per second (6.8)</source>
            <translation>Startgeschwindigkeit einer Fahrt in Schritten pro Sekunde (6.8)</translation>
        </message>
        <message>
            <source>Maximum frequency</source>
            <translation>Maximalfrequenz</translation>
        </message>
        <message>
            <source>Top speed reached after the acceleration ramp, in steps per second (6.9)</source>
            <translation>Nach der Beschleunigungsrampe erreichte Höchstgeschwindigkeit in Schritten pro Sekunde (6.9)</translation>
        </message>
        <message>
            <source>Maximum frequency 2</source>
            <translation>Maximalfrequenz 2</translation>
        </message>
        <message>
            <source>Top speed after the trigger in flag positioning mode (6.10)</source>
            <translation>Höchstgeschwindigkeit nach dem Trigger im Flag-Positioniermodus (6.10)</translation>
        </message>
        <message>
            <source>Ramp</source>
            <translation>Rampe</translation>
        </message>
        <message>
            <source>Acceleration and braking ramp: acceleration in Hz/ms = 3000 / sqrt(ramp) - 11.7 (6.11)</source>
            <translation>Beschleunigungs- und Bremsrampe: Beschleunigung in Hz/ms = 3000 / sqrt(Rampe) - 11,7 (6.11)</translation>
        </message>
        <message>
            <source>Direction</source>
            <translation>Richtung</translation>
        </message>
        <message>
            <source>left</source>
            <translation>links</translation>
        </message>
        <message>
            <source>right</source>
            <translation>rechts</translation>
        </message>
        <message>
            <source>Direction of rotation; 'right' counts positions up (6.12)</source>
            <translation>Drehrichtung; 'right' zählt die Position aufwärts (6.12)</translation>
        </message>
        <message>
            <source>Reverse on repetition</source>
            <translation>Richtungsumkehr bei Wiederholung</translation>
        </message>
        <message>
            <source>Reverse the direction on every repetition of the record (6.13)</source>
            <translation>Richtung bei jeder Wiederholung des Satzes umkehren (6.13)</translation>
        </message>
        <message>
            <source>Repetitions</source>
            <translation>Wiederholungen</translation>
        </message>
        <message>
            <source>Number of runs of the record; 0 repeats endlessly (6.14)</source>
            <translation>Anzahl der Durchläufe des Satzes; 0 wiederholt endlos (6.14)</translation>
        </message>
        <message>
            <source>Record pause</source>
            <translation>Satzpause</translation>
        </message>
        <message>
            <source>Pause between repetitions or before the next record (6.15)</source>
            <translation>Pause zwischen Wiederholungen oder vor dem Folgesatz (6.15)</translation>
        </message>
        <message>
            <source>Next record</source>
            <translation>Folgesatz</translation>
        </message>
        <message>
            <source>Record run after this one; 0: none (6.16)</source>
            <translation>Nach diesem ausgeführter Satz; 0: keiner (6.16)</translation>
        </message>
        <message>
            <source>Analog &amp; joystick</source>
            <translation>Analog &amp; Joystick</translation>
        </message>
        <message>
            <source>Joystick dead zone</source>
            <translation>Joystick-Totzone</translation>
        </message>
        <message>
            <source>Range around the middle of the analog input in which the motor stands still in joystick mode (7.1)</source>
            <translation>Bereich um die Mitte des Analogeingangs, in dem der Motor im Joystickmodus stillsteht (7.1)</translation>
        </message>
        <message>
            <source>Analog filter</source>
            <translation>Analogfilter</translation>
        </message>
        <message>
            <source>samples</source>
            <translation>Messwerte</translation>
        </message>
        <message>
            <source>Samples averaged for the analog input in analog and joystick mode (7.2)</source>
            <translation>Gemittelte Messwerte des Analogeingangs im Analog- und Joystickmodus (7.2)</translation>
        </message>
        <message>
            <source>Analog range start</source>
            <translation>Anfang des Analogbereichs</translation>
        </message>
        <message>
            <source>x0.1 V</source>
            <translation>x0,1 V</translation>
        </message>
        <message>
            <source>Start of the analog input range (7.3)</source>
            <translation>Anfang des Analogeingangsbereichs (7.3)</translation>
        </message>
        <message>
            <source>Analog range end</source>
            <translation>Ende des Analogbereichs</translation>
        </message>
        <message>
            <source>End of the analog input range (7.4)</source>
            <translation>Ende des Analogeingangsbereichs (7.4)</translation>
        </message>
        <message>
            <source>Analog input dead zone</source>
            <translation>Totzone des Analogeingangs</translation>
        </message>
        <message>
            <source>Dead zone of the analog input in percent of the range, joystick mode (7.5)</source>
            <translation>Totzone des Analogeingangs in Prozent des Bereichs, Joystickmodus (7.5)</translation>
        </message>
        <message>
            <source>Closed loop</source>
            <translation>Regelung (Closed Loop)</translation>
        </message>
        <message>
            <source>Closed loop enabled</source>
            <translation>Regelung eingeschaltet</translation>
        </message>
        <message>
            <source>Activates the control loop; only possible after the special reference run (mode 8) since power-on (8.1)</source>
            <translation>Aktiviert die Regelung; nur nach der speziellen Referenzfahrt (Modus 8) seit dem Einschalten möglich (8.1)</translation>
        </message>
        <message>
            <source>If pole pairs or encoder counts do not match the motor, or no calibration run was made for this motor, the motor can speed up beyond its mechanical limits (manual 8.1).</source>
            <translation>Passen Polpaare oder Encoderinkremente nicht zum Motor oder wurde für diesen Motor keine Kalibrierfahrt gemacht, kann der Motor über seine mechanischen Grenzen hinaus beschleunigen (Handbuch 8.1).</translation>
        </message>
        <message>
            <source>Position window</source>
            <translation>Positionsfenster</translation>
        </message>
        <message>
            <source>increments</source>
            <translation>Inkremente</translation>
        </message>
        <message>
            <source>Tolerance around the target that counts as reached (8.2)</source>
            <translation>Toleranz um das Ziel, die als erreicht gilt (8.2)</translation>
        </message>
        <message>
            <source>Position window time</source>
            <translation>Zeit im Positionsfenster</translation>
        </message>
        <message>
            <source>How long the position must stay in the window (8.3)</source>
            <translation>Wie lange die Position im Fenster bleiben muss (8.3)</translation>
        </message>
        <message>
            <source>Following error window</source>
            <translation>Schleppfehlerfenster</translation>
        </message>
        <message>
            <source>Largest allowed following error; beyond it a position error switches the loop off (8.4)</source>
            <translation>Größter erlaubter Schleppfehler; darüber schaltet ein Positionsfehler die Regelung ab (8.4)</translation>
        </message>
        <message>
            <source>Following error time</source>
            <translation>Schleppfehlerzeit</translation>
        </message>
        <message>
            <source>How long the following error may exceed the window (8.5)</source>
            <translation>Wie lange der Schleppfehler das Fenster überschreiten darf (8.5)</translation>
        </message>
        <message>
            <source>Motor pole pairs</source>
            <translation>Polpaare des Motors</translation>
        </message>
        <message>
            <source>Quarter of the full steps per revolution; changes step-angle as well (8.6)</source>
            <translation>Ein Viertel der Vollschritte je Umdrehung; ändert auch step-angle (8.6)</translation>
        </message>
        <message>
            <source>If pole pairs or encoder counts do not match the motor, or no calibration run was made for this motor, the motor can speed up beyond its mechanical limits (manual 8.1). The firmware must be restarted (power off) after a change.</source>
            <translation>Passen Polpaare oder Encoderinkremente nicht zum Motor oder wurde für diesen Motor keine Kalibrierfahrt gemacht, kann der Motor über seine mechanischen Grenzen hinaus beschleunigen (Handbuch 8.1). Nach einer Änderung muss die Firmware neu gestartet werden (Spannung aus).</translation>
        </message>
        <message>
            <source>Encoder increments</source>
            <translation>Encoderinkremente</translation>
        </message>
        <message>
            <source>Encoder increments per cl-encoder-revolutions (8.7)</source>
            <translation>Encoderinkremente je cl-encoder-revolutions (8.7)</translation>
        </message>
        <message>
            <source>Encoder revolutions</source>
            <translation>Encoderumdrehungen</translation>
        </message>
        <message>
            <source>Shaft revolutions for cl-encoder-increments; always 1 (8.8)</source>
            <translation>Wellenumdrehungen für cl-encoder-increments; immer 1 (8.8)</translation>
        </message>
        <message>
            <source>Other values stop the control loop from working. The firmware must be restarted (power off) after a change.</source>
            <translation>Andere Werte setzen die Regelung außer Funktion. Nach einer Änderung muss die Firmware neu gestartet werden (Spannung aus).</translation>
        </message>
        <message>
            <source>Speed loop P numerator</source>
            <translation>Drehzahlregler P-Zähler</translation>
        </message>
        <message>
            <source>Numerator of the controller term (8.9-8.20)</source>
            <translation>Zähler des Reglerterms (8.9-8.20)</translation>
        </message>
        <message>
            <source>Speed loop P denominator</source>
            <translation>Drehzahlregler P-Nenner</translation>
        </message>
        <message>
            <source>2^n</source>
            <translation>2^n</translation>
        </message>
        <message>
            <source>Denominator of the controller term as a power of two: 0 = 1, 1 = 2, 2 = 4, ... (8.9-8.20)</source>
            <translation>Nenner des Reglerterms als Zweierpotenz: 0 = 1, 1 = 2, 2 = 4, ... (8.9-8.20)</translation>
        </message>
        <message>
            <source>Speed loop I numerator</source>
            <translation>Drehzahlregler I-Zähler</translation>
        </message>
        <message>
            <source>Speed loop I denominator</source>
            <translation>Drehzahlregler I-Nenner</translation>
        </message>
        <message>
            <source>Speed loop D numerator</source>
            <translation>Drehzahlregler D-Zähler</translation>
        </message>
        <message>
            <source>Speed loop D denominator</source>
            <translation>Drehzahlregler D-Nenner</translation>
        </message>
        <message>
            <source>Position loop P numerator</source>
            <translation>Lageregler P-Zähler</translation>
        </message>
        <message>
            <source>Position loop P denominator</source>
            <translation>Lageregler P-Nenner</translation>
        </message>
        <message>
            <source>Position loop I numerator</source>
            <translation>Lageregler I-Zähler</translation>
        </message>
        <message>
            <source>Position loop I denominator</source>
            <translation>Lageregler I-Nenner</translation>
        </message>
        <message>
            <source>Position loop D numerator</source>
            <translation>Lageregler D-Zähler</translation>
        </message>
        <message>
            <source>Position loop D denominator</source>
            <translation>Lageregler D-Nenner</translation>
        </message>
        <message>
            <source>Status</source>
            <translation>Status</translation>
        </message>
        <message>
            <source>Position</source>
            <translation>Position</translation>
        </message>
        <message>
            <source>Position in steps of the current step mode, relative to the last reference (5.17)</source>
            <translation>Position in Schritten der aktuellen Schrittweite, bezogen auf die letzte Referenz (5.17)</translation>
        </message>
        <message>
            <source>Encoder position</source>
            <translation>Encoderposition</translation>
        </message>
        <message>
            <source>Position according to the encoder (5.16)</source>
            <translation>Position laut Encoder (5.16)</translation>
        </message>
        <message>
            <source>Bit 0 ready, 1 zero position reached, 2 position error, 3 input 1 set while ready, 4-6 mode (5.21)</source>
            <translation>Bit 0 bereit, 1 Nullposition erreicht, 2 Positionsfehler, 3 Eingang 1 gesetzt, obwohl bereit, 4-6 Modus (5.21)</translation>
        </message>
        <message>
            <source>Bus address</source>
            <translation>Busadresse</translation>
        </message>
        <message>
            <source>The address the drive answers at (5.20)</source>
            <translation>Die Adresse, unter der die Steuerung antwortet (5.20)</translation>
        </message>
        <message>
            <source>Last error</source>
            <translation>Letzter Fehler</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keiner</translation>
        </message>
        <message>
            <source>low-voltage</source>
            <translation>Unterspannung</translation>
        </message>
        <message>
            <source>over-temperature</source>
            <translation>Übertemperatur</translation>
        </message>
        <message>
            <source>driver</source>
            <translation>Treiber</translation>
        </message>
        <message>
            <source>eeprom</source>
            <translation>EEPROM</translation>
        </message>
        <message>
            <source>position</source>
            <translation>Position</translation>
        </message>
        <message>
            <source>internal</source>
            <translation>intern</translation>
        </message>
        <message>
            <source>Most recent entry of the error memory (5.15)</source>
            <translation>Jüngster Eintrag des Fehlerspeichers (5.15)</translation>
        </message>
        <message>
            <source>The drive sends its status ('j') by itself at the end of every move (5.31). StepDeck polls the bus and switches this off when it connects</source>
            <translation>Die Steuerung sendet ihren Status ('j') am Ende jeder Fahrt von selbst (5.31). StepDeck fragt den Bus zyklisch ab und schaltet dies beim Verbinden aus</translation>
        </message>
        <message>
            <source>On a half-duplex RS485 bus that is being polled, a status the drive sends by itself collides with the poll of another drive. StepDeck switches it off again on the next connect.</source>
            <translation>Auf einem abgefragten Halbduplex-RS485-Bus kollidiert ein von der Steuerung selbst gesendeter Status mit der Abfrage einer anderen Steuerung. StepDeck schaltet ihn beim nächsten Verbinden wieder aus.</translation>
        </message>
        <message>
            <source>Speed at which every move starts and ends its ramp (#S, 9.4)</source>
            <translation>Geschwindigkeit, mit der jede Fahrt ihre Rampe beginnt und beendet (#S, 9.4)</translation>
        </message>
        <message>
            <source>Work speed</source>
            <translation>Arbeitsgeschwindigkeit</translation>
        </message>
        <message>
            <source>Speed of vector moves after the ramp (#E1, 9.5)</source>
            <translation>Geschwindigkeit der Vektorfahrten nach der Rampe (#E1, 9.5)</translation>
        </message>
        <message>
            <source>Time from start speed to work speed and back, all motors (#R, 9.6)</source>
            <translation>Zeit von der Start- zur Arbeitsgeschwindigkeit und zurück, alle Motoren (#R, 9.6)</translation>
        </message>
        <message>
            <source>Referencing</source>
            <translation>Referenzfahrt</translation>
        </message>
        <message>
            <source>Reference speed</source>
            <translation>Referenzgeschwindigkeit</translation>
        </message>
        <message>
            <source>Speed of reference runs, one value for all motors (#E9, 9.5)</source>
            <translation>Geschwindigkeit der Referenzfahrten, ein Wert für alle Motoren (#E9, 9.5)</translation>
        </message>
        <message>
            <source>Offset after referencing</source>
            <translation>Offset nach Referenzfahrt</translation>
        </message>
        <message>
            <source>Steps the motor moves out of its switch after a reference run (#O, 9.10); not a system parameter</source>
            <translation>Schritte, die der Motor nach der Referenzfahrt aus dem Schalter fährt (#O, 9.10); kein Systemparameter</translation>
        </message>
        <message>
            <source>Reference switch type</source>
            <translation>Referenzschaltertyp</translation>
        </message>
        <message>
            <source>NO: normally open (Schließer, the default), NC: normally closed (Öffner); inputs 1-4 (##REFSW, 9.14, 5.2.1)</source>
            <translation>NO: Schließer (Standard), NC: Öffner; Eingänge 1-4 (##REFSW, 9.14, 5.2.1)</translation>
        </message>
        <message>
            <source>NO</source>
            <translation>NO</translation>
        </message>
        <message>
            <source>NC</source>
            <translation>NC</translation>
        </message>
        <message>
            <source>The type must match the wired switches, or reference runs end in the wrong place. It is stored in the board's system parameters and kept after power-off.</source>
            <translation>Der Typ muss zu den verdrahteten Schaltern passen, sonst enden Referenzfahrten an der falschen Stelle. Er wird in den Systemparametern der Steuerung gespeichert und bleibt nach dem Ausschalten erhalten.</translation>
        </message>
        <message>
            <source>Drive</source>
            <translation>Antrieb</translation>
        </message>
        <message>
            <source>Step resolution</source>
            <translation>Schrittauflösung</translation>
        </message>
        <message>
            <source>microsteps</source>
            <translation>Mikroschritte</translation>
        </message>
        <message>
            <source>Microsteps per full step (D, 9.7)</source>
            <translation>Mikroschritte je Vollschritt (D, 9.7)</translation>
        </message>
        <message>
            <source>Changes the length of a step: every position, distance and speed in steps changes its meaning.</source>
            <translation>Ändert die Länge eines Schritts: jede Position, Strecke und Geschwindigkeit in Schritten bekommt eine andere Bedeutung.</translation>
        </message>
        <message>
            <source>Run current</source>
            <translation>Arbeitsstrom</translation>
        </message>
        <message>
            <source>Motor current while moving, % of the driver's rating (c, 9.8)</source>
            <translation>Motorstrom während der Fahrt, % vom Nennstrom der Endstufe (c, 9.8)</translation>
        </message>
        <message>
            <source>A current above the motor's rating overheats motor and driver stage.</source>
            <translation>Ein Strom über dem Nennstrom des Motors überhitzt Motor und Endstufe.</translation>
        </message>
        <message>
            <source>Motor current at standstill, % of the driver's rating (c, 9.8); 0 leaves the motor without holding torque</source>
            <translation>Motorstrom im Stillstand, % vom Nennstrom der Endstufe (c, 9.8); 0 lässt den Motor ohne Haltemoment</translation>
        </message>
        <message>
            <source>Interpolation</source>
            <translation>Interpolation</translation>
        </message>
        <message>
            <source>On: the axes of a vector move arrive together; off: each axis moves at its own speed (IP, 9.12)</source>
            <translation>Ein: die Achsen einer Vektorfahrt kommen gleichzeitig ins Ziel; aus: jede Achse fährt mit ihrer eigenen Geschwindigkeit (IP, 9.12)</translation>
        </message>
        <message>
            <source>closed-loop-reference</source>
            <translation>Regelungs-Referenzfahrt</translation>
        </message>
        <message>
            <source>calibration</source>
            <translation>Kalibrierfahrt</translation>
        </message>
        <message>
            <source>Operating mode (5.5, 8.1). Moves, jog and reference runs switch the mode themselves; the closed-loop workflow runs calibration and closed-loop-reference and sets the mode of before again afterwards.</source>
            <translation>Betriebsart (5.5, 8.1). Fahrten, Tippbetrieb und Referenzfahrten stellen den Modus selbst um; die Inbetriebnahme der Regelung fährt Kalibrierfahrt und Regelungs-Referenzfahrt und stellt danach den vorherigen Modus wieder ein.</translation>
        </message>
        <message>
            <source>(no unit)</source>
            <translation>(keine Einheit)</translation>
        </message>
        <message>
            <source>The E-LAB manual gives no unit for the acceleration, only its scale: the larger the value, the steeper the ramp (SetAcceleration).</source>
            <translation>Das E-LAB-Handbuch nennt für die Beschleunigung keine Einheit, nur ihre Skala: je größer der Wert, desto steiler die Rampe (SetAcceleration).</translation>
        </message>
    </context>
    <context>
        <name>Units</name>
        <message>
            <source>steps</source>
            <translation>Schritte</translation>
        </message>
        <message>
            <source>units</source>
            <translation>Einheiten</translation>
        </message>
    </context>
    <context>
        <name>main</name>
        <message>
            <source>unknown model '%1' (known: %2)</source>
            <translation>unbekanntes Modell '%1' (bekannt: %2)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::AxisNames</name>
        <message>
            <source>'%1' is not an axis name (X, Y, Z, U, or a letter and then letters, digits or _, 2 to %2 characters)</source>
            <translation>„%1“ ist kein Achsname (X, Y, Z, U oder ein Buchstabe, dann Buchstaben, Ziffern oder _, 2 bis %2 Zeichen)</translation>
        </message>
        <message>
            <source>%1 is the name of another axis</source>
            <translation>%1 ist der Name einer anderen Achse</translation>
        </message>
        <message>
            <source>%1 names two axes</source>
            <translation>%1 benennt zwei Achsen</translation>
        </message>
        <message>
            <source>%1 is given twice</source>
            <translation>%1 ist zweimal angegeben</translation>
        </message>
        <message>
            <source>more than %1 axes</source>
            <translation>mehr als %1 Achsen</translation>
        </message>
        <message>
            <source>expected NAME=ADDRESS (e.g. feeder=5), got '%1'</source>
            <translation>NAME=ADRESSE erwartet (z. B. feeder=5), erhalten: „%1“</translation>
        </message>
        <message>
            <source>%1: '%2' is not a whole bus address</source>
            <translation>%1: „%2“ ist keine ganze Busadresse</translation>
        </message>
        <message>
            <source>no axis given (e.g. X=1,Y=2 or feeder=5,gate=6)</source>
            <translation>keine Achse angegeben (z. B. X=1,Y=2 oder feeder=5,gate=6)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::Controller</name>
        <message>
            <source>this machine has no axis %1</source>
            <translation>diese Maschine hat keine Achse %1</translation>
        </message>
        <message>
            <source>absolute move refused: position of axis %1 is unknown, reference it first</source>
            <translation>Absolutfahrt abgelehnt: Position der Achse %1 ist unbekannt, zuerst referenzieren</translation>
        </message>
        <message>
            <source>this controller has no feed mode</source>
            <translation>diese Steuerung hat keinen Vorschubbetrieb</translation>
        </message>
        <message>
            <source>this controller has no single-step feed stream</source>
            <translation>diese Steuerung hat keinen Einzelschritt-Vorschubstrom</translation>
        </message>
        <message>
            <source>this controller has no velocity move</source>
            <translation>diese Steuerung hat keine Geschwindigkeitsfahrt</translation>
        </message>
        <message>
            <source>this controller has no reset</source>
            <translation>diese Steuerung hat keinen Reset</translation>
        </message>
        <message>
            <source>this controller has no spindle output</source>
            <translation>diese Steuerung hat keinen Spindelausgang</translation>
        </message>
        <message>
            <source>this controller has no coolant output</source>
            <translation>diese Steuerung hat keinen Kühlmittelausgang</translation>
        </message>
        <message>
            <source>this controller has no drive power setting</source>
            <translation>diese Steuerung hat keine Einstellung des Motorstroms</translation>
        </message>
        <message>
            <source>this controller has no bus to scan</source>
            <translation>diese Steuerung hat keinen Bus zum Durchsuchen</translation>
        </message>
        <message>
            <source>this controller has no operation '%1'</source>
            <translation>diese Steuerung kennt die Operation '%1' nicht</translation>
        </message>
        <message>
            <source>jog refused: not connected</source>
            <translation>Tippbetrieb abgelehnt: nicht verbunden</translation>
        </message>
        <message>
            <source>jog refused: emergency stop is active</source>
            <translation>Tippbetrieb abgelehnt: Not-Aus ist aktiv</translation>
        </message>
        <message>
            <source>this controller has no stop command: use the machine's emergency stop to stop it; motion only ends when the current move arrives</source>
            <translation>diese Steuerung hat keinen Stopp-Befehl: zum Anhalten den Not-Halt der Maschine benutzen; eine Bewegung endet erst, wenn die laufende Fahrt ihr Ziel erreicht</translation>
        </message>
        <message>
            <source>the controller did not confirm the stop and may still be moving: use the machine's emergency stop</source>
            <translation>die Steuerung hat den Stopp nicht bestätigt und bewegt sich womöglich noch: den Not-Halt der Maschine benutzen</translation>
        </message>
        <message>
            <source>link closed</source>
            <translation>Verbindung geschlossen</translation>
        </message>
        <message>
            <source>closed</source>
            <translation>geschlossen</translation>
        </message>
        <message>
            <source>link lost: %1</source>
            <translation>Verbindung verloren: %1</translation>
        </message>
        <message>
            <source>link lost: %1; %2</source>
            <translation>Verbindung verloren: %1; %2</translation>
        </message>
        <message>
            <source>this controller cannot run a contour as a step stream</source>
            <translation>diese Steuerung kann keine Kontur als Schrittstrom fahren</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ControllerSession</name>
        <message>
            <source>unknown controller model '%1' (known: %2)</source>
            <translation>unbekanntes Steuerungsmodell '%1' (bekannt: %2)</translation>
        </message>
        <message>
            <source>no controller session</source>
            <translation>keine Steuerungssitzung</translation>
        </message>
        <message>
            <source>model %1 cannot be built in this program</source>
            <translation>Modell %1 kann in diesem Programm nicht erzeugt werden</translation>
        </message>
        <message>
            <source>unknown controller model '%1' (did you mean %2? known: %3)</source>
            <translation>unbekanntes Steuerungsmodell '%1' (meinten Sie %2? bekannt: %3)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ModelPresentation</name>
        <message>
            <source>bad hex escape at column %1</source>
            <translation>ungültige Hex-Angabe in Spalte %1</translation>
        </message>
        <message>
            <source>non-ASCII character at column %1</source>
            <translation>Nicht-ASCII-Zeichen in Spalte %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ParameterFile</name>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>%1 kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>Cannot open %1: %2</source>
            <translation>%1 kann nicht geöffnet werden: %2</translation>
        </message>
        <message>
            <source>%1, line %2, column %3: %4</source>
            <translation>%1, Zeile %2, Spalte %3: %4</translation>
        </message>
        <message>
            <source>%1 is not a parameter file: it holds no JSON object</source>
            <translation>%1 ist keine Parameterdatei: sie enthält kein JSON-Objekt</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1 is empty: a StepDeck parameter file holds a JSON object with the parameters</source>
            <translation>%1 ist leer: Eine StepDeck-Parameterdatei enthält ein JSON-Objekt mit den Parametern</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ParameterSchema</name>
        <message>
            <source>%1: value '%2' is out of range (allowed: %3%4)</source>
            <translation>%1: Wert '%2' liegt außerhalb des Bereichs (erlaubt: %3%4)</translation>
        </message>
        <message>
            <source>unknown parameter '%1'</source>
            <translation>unbekannter Parameter '%1'</translation>
        </message>
        <message>
            <source>%1 is read-only</source>
            <translation>%1 ist nur lesbar</translation>
        </message>
        <message>
            <source>%1 needs one value per axis</source>
            <translation>%1 braucht einen Wert pro Achse</translation>
        </message>
        <message>
            <source>%1: this machine has no axis %2</source>
            <translation>%1: diese Maschine hat keine Achse %2</translation>
        </message>
        <message>
            <source>%1 takes a single value, not one per axis</source>
            <translation>%1 nimmt einen einzelnen Wert, nicht einen pro Achse</translation>
        </message>
        <message>
            <source>expected NAME=VALUE, got '%1'</source>
            <translation>NAME=WERT erwartet, erhalten: '%1'</translation>
        </message>
        <message>
            <source>%1 needs 1 or %2 values (axes %3)</source>
            <translation>%1 braucht 1 oder %2 Werte (Achsen %3)</translation>
        </message>
        <message>
            <source>%1 takes a single value</source>
            <translation>%1 nimmt einen einzelnen Wert</translation>
        </message>
        <message>
            <source>not a StepDeck parameter file</source>
            <translation>keine StepDeck-Parameterdatei</translation>
        </message>
        <message>
            <source>unsupported parameter file version %1</source>
            <translation>nicht unterstützte Version %1 der Parameterdatei</translation>
        </message>
        <message>
            <source>parameter file is for model '%1', not '%2'</source>
            <translation>Parameterdatei ist für Modell '%1', nicht '%2'</translation>
        </message>
        <message>
            <source>parameter file has no "parameters" object</source>
            <translation>Parameterdatei hat kein Objekt "parameters"</translation>
        </message>
        <message>
            <source>%1: '%2' is not an axis</source>
            <translation>%1: '%2' ist keine Achse</translation>
        </message>
        <message>
            <source>%1: '%2' is not a decimal integer (allowed: %3%4)</source>
            <translation>%1: '%2' ist keine ganze Dezimalzahl (erlaubt: %3%4)</translation>
        </message>
        <message>
            <source>%1: '%2' is not a finite number (allowed: %3%4)</source>
            <translation>%1: '%2' ist keine endliche Zahl (erlaubt: %3%4)</translation>
        </message>
        <message>
            <source>unknown parameter '%1' (did you mean %2?)</source>
            <translation>unbekannter Parameter '%1' (meinten Sie %2?)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::PtyEndpoint</name>
        <message>
            <source>cannot create a pseudo-terminal: %1</source>
            <translation>Pseudo-Terminal kann nicht angelegt werden: %1</translation>
        </message>
        <message>
            <source>cannot configure the pseudo-terminal: %1</source>
            <translation>Pseudo-Terminal kann nicht eingestellt werden: %1</translation>
        </message>
        <message>
            <source>pseudo-terminal %1: write failed: %2</source>
            <translation>Pseudo-Terminal %1: Schreiben fehlgeschlagen: %2</translation>
        </message>
        <message>
            <source>pseudo-terminal %1: read failed: %2</source>
            <translation>Pseudo-Terminal %1: Lesen fehlgeschlagen: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::SerialPortAccess</name>
        <message>
            <source>serial port %1 is in use by another program</source>
            <translation>serielle Schnittstelle %1 wird von einem anderen Programm benutzt</translation>
        </message>
        <message>
            <source>serial port %1: access denied although you are in its group '%2': check the device's permissions (ls -l %1)</source>
            <translation>serielle Schnittstelle %1: Zugriff verweigert, obwohl Sie in ihrer Gruppe '%2' sind: Prüfen Sie die Rechte des Geräts (ls -l %1)</translation>
        </message>
        <message>
            <source>serial port %1: access denied: you were added to the group '%2', but this session does not have it yet: log out and in again</source>
            <translation>serielle Schnittstelle %1: Zugriff verweigert: Sie wurden der Gruppe '%2' hinzugefügt, diese Sitzung hat sie aber noch nicht: Melden Sie sich ab und wieder an</translation>
        </message>
        <message>
            <source>serial port %1: access denied: your user is not in the group '%2' that owns it. Join it (sudo adduser %3 %2), then log out and in again</source>
            <translation>serielle Schnittstelle %1: Zugriff verweigert: Ihr Benutzer ist nicht in der Gruppe '%2', der sie gehört. Treten Sie ihr bei (sudo adduser %3 %2) und melden Sie sich dann ab und wieder an</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::SerialTransport</name>
        <message>
            <source>serial port %1 does not support %2 baud, %3%4%5</source>
            <translation>serielle Schnittstelle %1 unterstützt %2 Baud, %3%4%5 nicht</translation>
        </message>
        <message>
            <source>no serial port given</source>
            <translation>keine serielle Schnittstelle angegeben</translation>
        </message>
        <message>
            <source>serial port %1 is not open</source>
            <translation>serielle Schnittstelle %1 ist nicht geöffnet</translation>
        </message>
        <message>
            <source>serial port %1 is already open</source>
            <translation>serielle Schnittstelle %1 ist bereits geöffnet</translation>
        </message>
        <message>
            <source>serial port %1 lost: the device vanished</source>
            <translation>serielle Schnittstelle %1 verloren: das Gerät ist verschwunden</translation>
        </message>
        <message>
            <source>serial port %1 lost: writing to it failed</source>
            <translation>serielle Schnittstelle %1 verloren: Schreiben fehlgeschlagen</translation>
        </message>
        <message>
            <source>serial port %1 refused an operation: %2</source>
            <translation>serielle Schnittstelle %1 hat eine Operation abgelehnt: %2</translation>
        </message>
        <message>
            <source>serial port %1 failed: %2</source>
            <translation>serielle Schnittstelle %1 fehlgeschlagen: %2</translation>
        </message>
        <message>
            <source>serial port %1 cannot drive %2: %3</source>
            <translation>serielle Schnittstelle %1 kann %2 nicht schalten: %3</translation>
        </message>
        <message>
            <source>no such port: %1</source>
            <translation>Schnittstelle existiert nicht: %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::SoftLimits</name>
        <message>
            <source>refused: axis %1 would reach %2, beyond its soft limit %3</source>
            <translation>abgelehnt: Achse %1 würde %2 erreichen, jenseits ihres Software-Endschalters %3</translation>
        </message>
        <message>
            <source>refused: a velocity move has no end, and axis %1 has soft limits; jog or move to a position instead</source>
            <translation>abgelehnt: Eine Geschwindigkeitsfahrt hat kein Ende, und Achse %1 hat Software-Endschalter; stattdessen tippen oder eine Position anfahren</translation>
        </message>
        <message>
            <source>jog stopped: axis %1 at its soft limit %2</source>
            <translation>Tippbetrieb angehalten: Achse %1 an ihrem Software-Endschalter %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::TargetJogger</name>
        <message>
            <source>Jog ended: axis %1 reached its end switch</source>
            <translation>Tippbetrieb beendet: Achse %1 hat ihren Endschalter erreicht</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::TcpTransport</name>
        <message>
            <source>%1: no connection within %2 ms</source>
            <translation>%1: keine Verbindung innerhalb von %2 ms</translation>
        </message>
        <message>
            <source>"%1" is not a TCP address; expected tcp://HOST:PORT</source>
            <translation>"%1" ist keine TCP-Adresse; erwartet tcp://HOST:PORT</translation>
        </message>
        <message>
            <source>"%1" names no host; expected tcp://HOST:PORT</source>
            <translation>"%1" nennt keinen Host; erwartet tcp://HOST:PORT</translation>
        </message>
        <message>
            <source>"%1" needs a port between 1 and 65535; expected tcp://HOST:PORT</source>
            <translation>"%1" braucht einen Port zwischen 1 und 65535; erwartet tcp://HOST:PORT</translation>
        </message>
        <message>
            <source>"%1" has a path; expected tcp://HOST:PORT</source>
            <translation>"%1" enthält einen Pfad; erwartet tcp://HOST:PORT</translation>
        </message>
        <message>
            <source>"%1" has extra parts; expected tcp://HOST:PORT</source>
            <translation>"%1" enthält zusätzliche Teile; erwartet tcp://HOST:PORT</translation>
        </message>
        <message>
            <source>%1 lost: the device server closed the connection</source>
            <translation>%1 verloren: der Geräteserver hat die Verbindung geschlossen</translation>
        </message>
        <message>
            <source>%1: connection refused</source>
            <translation>%1: Verbindung abgewiesen</translation>
        </message>
        <message>
            <source>%1: host not found</source>
            <translation>%1: Host nicht gefunden</translation>
        </message>
        <message>
            <source>%1 lost: %2</source>
            <translation>%1 verloren: %2</translation>
        </message>
        <message>
            <source>%1: cannot connect: %2</source>
            <translation>%1: Verbindung nicht möglich: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::Transport</name>
        <message>
            <source>this link has no modem control lines</source>
            <translation>diese Verbindung hat keine Modem-Steuerleitungen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::bridge::LaserBridge</name>
        <message>
            <source>the controller did not confirm the stop in time</source>
            <translation>die Steuerung hat den Stopp nicht rechtzeitig bestätigt</translation>
        </message>
        <message>
            <source>no controller session or laser port</source>
            <translation>keine Steuerungsverbindung oder kein Laser-Port</translation>
        </message>
        <message>
            <source>serving the laser on %1 (9600 8N1): laser axes %2, %3 steps per laser unit</source>
            <translation>bediene den Laser an %1 (9600 8N1): Laserachsen %2, %3 Schritte pro Lasereinheit</translation>
        </message>
        <message>
            <source>laser port: %1</source>
            <translation>Laser-Port: %1</translation>
        </message>
        <message>
            <source>ignored malformed frame: %1</source>
            <translation>fehlerhaften Rahmen ignoriert: %1</translation>
        </message>
        <message>
            <source>laser axis %1 is not mapped to a controller axis</source>
            <translation>Laserachse %1 ist keiner Steuerungsachse zugeordnet</translation>
        </message>
        <message>
            <source>the bridge is stopping</source>
            <translation>die Brücke wird angehalten</translation>
        </message>
        <message>
            <source>door open: %1 waits until the door closes</source>
            <translation>Tür offen: %1 wartet, bis die Tür geschlossen ist</translation>
        </message>
        <message>
            <source>door opened</source>
            <translation>Tür geöffnet</translation>
        </message>
        <message>
            <source>door closed</source>
            <translation>Tür geschlossen</translation>
        </message>
        <message>
            <source>stopping the motion the bridge started</source>
            <translation>stoppe die Bewegung, die die Brücke gestartet hat</translation>
        </message>
        <message>
            <source>the controller has no stop command: the axes go on to their targets; use the machine's emergency stop to stop them</source>
            <translation>die Steuerung hat keinen Stoppbefehl: die Achsen fahren weiter zu ihren Zielen; zum Anhalten den Not-Halt der Maschine benutzen</translation>
        </message>
        <message>
            <source>laser bridge stopped</source>
            <translation>Laserbrücke angehalten</translation>
        </message>
        <message>
            <source>laser  -&gt;</source>
            <translation>Laser  -&gt;</translation>
        </message>
        <message>
            <source>laser &lt;- </source>
            <translation>Laser &lt;- </translation>
        </message>
        <message>
            <source>ignored  </source>
            <translation>ignoriert</translation>
        </message>
        <message>
            <source>note     </source>
            <translation>Hinweis  </translation>
        </message>
        <message>
            <source>ERROR    </source>
            <translation>FEHLER   </translation>
        </message>
        <message>
            <source>idle</source>
            <translation>bereit</translation>
        </message>
        <message>
            <source>referencing</source>
            <translation>referenziert gerade</translation>
        </message>
        <message>
            <source>moving</source>
            <translation>fährt</translation>
        </message>
        <message>
            <source>waiting for the controller</source>
            <translation>wartet auf die Steuerung</translation>
        </message>
        <message>
            <source>stopping to retarget</source>
            <translation>stoppt für ein neues Ziel</translation>
        </message>
        <message>
            <source>%1: %2; no answer to the laser (it raises its timeout alarm)</source>
            <translation>%1: %2; keine Antwort an den Laser (er meldet seinen Zeitüberschreitungsalarm)</translation>
        </message>
        <message>
            <source>the controller is not connected</source>
            <translation>die Steuerung ist nicht verbunden</translation>
        </message>
        <message>
            <source>the operator is jogging axis %1</source>
            <translation>der Bediener verfährt Achse %1 im Tippbetrieb</translation>
        </message>
        <message>
            <source>axis %1 not referenced since the bridge started: referencing it first</source>
            <translation>Achse %1 ist seit dem Start der Brücke nicht referenziert: zuerst Referenzfahrt</translation>
        </message>
        <message>
            <source>target x scale is out of range</source>
            <translation>Ziel x Maßstab liegt außerhalb des Bereichs</translation>
        </message>
        <message>
            <source>new target for axis %1 while it moves: stopping first</source>
            <translation>neues Ziel für Achse %1 während der Fahrt: zuerst stoppen</translation>
        </message>
        <message>
            <source>new target for axis %1 while it moves: the controller cannot retarget without a ramped stop, so it arrives first</source>
            <translation>neues Ziel für Achse %1 während der Fahrt: die Steuerung kann ohne Stopp mit Rampe kein neues Ziel anfahren, daher kommt sie zuerst an</translation>
        </message>
        <message>
            <source>the controller has no stop command: the axes go on to their targets</source>
            <translation>die Steuerung hat keinen Stoppbefehl: die Achsen fahren weiter zu ihren Zielen</translation>
        </message>
        <message>
            <source>the controller's status could not be read: %1</source>
            <translation>der Status der Steuerung konnte nicht gelesen werden: %1</translation>
        </message>
        <message>
            <source>controller refused at an active limit switch: %1</source>
            <translation>Steuerung lehnt an einem aktiven Endschalter ab: %1</translation>
        </message>
        <message>
            <source>axis %1 waits until the controller is idle (%2)</source>
            <translation>Achse %1 wartet, bis die Steuerung bereit ist (%2)</translation>
        </message>
        <message>
            <source>the controller did not take it: %1</source>
            <translation>die Steuerung hat es nicht angenommen: %1</translation>
        </message>
        <message>
            <source>the operator took over axis %1</source>
            <translation>der Bediener hat Achse %1 übernommen</translation>
        </message>
        <message>
            <source>stop failed: %1</source>
            <translation>Stopp fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>status after the stop: %1</source>
            <translation>Status nach dem Stopp: %1</translation>
        </message>
        <message>
            <source>not reported to the laser: %1</source>
            <translation>dem Laser nicht gemeldet: %1</translation>
        </message>
        <message>
            <source>target not reached</source>
            <translation>Ziel nicht erreicht</translation>
        </message>
        <message>
            <source>the controller's link was lost</source>
            <translation>die Verbindung zur Steuerung ist verloren</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::Codec</name>
        <message>
            <source>reply interrupted by a new control byte</source>
            <translation>Antwort durch ein neues Steuerzeichen unterbrochen</translation>
        </message>
        <message>
            <source>unexpected control byte</source>
            <translation>unerwartetes Steuerzeichen</translation>
        </message>
        <message>
            <source>bytes outside a reply</source>
            <translation>Bytes außerhalb einer Antwort</translation>
        </message>
        <message>
            <source>malformed reply</source>
            <translation>fehlerhafte Antwort</translation>
        </message>
        <message>
            <source>step byte has bit 7 or bit 3 set</source>
            <translation>Schrittbyte hat Bit 7 oder Bit 3 gesetzt</translation>
        </message>
        <message>
            <source>command interrupted by a new control byte</source>
            <translation>Befehl durch ein neues Steuerzeichen unterbrochen</translation>
        </message>
        <message>
            <source>bytes outside a command</source>
            <translation>Bytes außerhalb eines Befehls</translation>
        </message>
        <message>
            <source>unknown command byte</source>
            <translation>unbekanntes Befehlsbyte</translation>
        </message>
        <message>
            <source>malformed parameters</source>
            <translation>fehlerhafte Parameter</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keiner</translation>
        </message>
        <message>
            <source>motors are powered</source>
            <translation>Motoren sind bestromt</translation>
        </message>
        <message>
            <source>spindle motor is on</source>
            <translation>Spindelmotor ist eingeschaltet</translation>
        </message>
        <message>
            <source>axes are moving</source>
            <translation>Achsen sind in Bewegung</translation>
        </message>
        <message>
            <source>serial port fault (not implemented)</source>
            <translation>Fehler der seriellen Schnittstelle (nicht implementiert)</translation>
        </message>
        <message>
            <source>internal error (not implemented)</source>
            <translation>interner Fehler (nicht implementiert)</translation>
        </message>
        <message>
            <source>parameter error (not implemented)</source>
            <translation>Parameterfehler (nicht implementiert)</translation>
        </message>
        <message>
            <source>internal temperature above 50 °C</source>
            <translation>Innentemperatur über 50 °C</translation>
        </message>
        <message>
            <source>setup incomplete: start speed, max speed and acceleration not all set</source>
            <translation>Einrichtung unvollständig: Startgeschwindigkeit, Maximalgeschwindigkeit und Beschleunigung nicht alle gesetzt</translation>
        </message>
        <message>
            <source>a limit switch of the X axis is active</source>
            <translation>ein Endschalter der X-Achse ist aktiv</translation>
        </message>
        <message>
            <source>a limit switch of the Y axis is active</source>
            <translation>ein Endschalter der Y-Achse ist aktiv</translation>
        </message>
        <message>
            <source>a limit switch of the Z axis is active</source>
            <translation>ein Endschalter der Z-Achse ist aktiv</translation>
        </message>
        <message>
            <source>the X reference switch is active</source>
            <translation>der Referenzschalter der X-Achse ist aktiv</translation>
        </message>
        <message>
            <source>the Y reference switch is active</source>
            <translation>der Referenzschalter der Y-Achse ist aktiv</translation>
        </message>
        <message>
            <source>the Z reference switch is active</source>
            <translation>der Referenzschalter der Z-Achse ist aktiv</translation>
        </message>
        <message>
            <source>the panic (emergency stop) switch is active</source>
            <translation>der Panik-Schalter (Not-Aus) ist aktiv</translation>
        </message>
        <message>
            <source>X axis in FastMove or feed mode</source>
            <translation>X-Achse im FastMove- oder Vorschubbetrieb</translation>
        </message>
        <message>
            <source>X axis in jog mode</source>
            <translation>X-Achse im Tippbetrieb</translation>
        </message>
        <message>
            <source>Y axis in FastMove or feed mode</source>
            <translation>Y-Achse im FastMove- oder Vorschubbetrieb</translation>
        </message>
        <message>
            <source>Y axis in jog mode</source>
            <translation>Y-Achse im Tippbetrieb</translation>
        </message>
        <message>
            <source>Z axis in FastMove or feed mode</source>
            <translation>Z-Achse im FastMove- oder Vorschubbetrieb</translation>
        </message>
        <message>
            <source>Z axis in jog mode</source>
            <translation>Z-Achse im Tippbetrieb</translation>
        </message>
        <message>
            <source>a limit switch is active</source>
            <translation>ein Endschalter ist aktiv</translation>
        </message>
        <message>
            <source>a reference switch is active</source>
            <translation>ein Referenzschalter ist aktiv</translation>
        </message>
        <message>
            <source>character %1 at position %2 is not ASCII</source>
            <translation>Zeichen %1 an Position %2 ist kein ASCII</translation>
        </message>
        <message>
            <source>'&lt;' at position %1 is not closed</source>
            <translation>'&lt;' an Position %1 ist nicht geschlossen</translation>
        </message>
        <message>
            <source>unknown mnemonic &lt;%1&gt; at position %2</source>
            <translation>unbekanntes Kürzel &lt;%1&gt; an Position %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::ElabController</name>
        <message>
            <source>no reply to %1 status polls in a row</source>
            <translation>keine Antwort auf %1 Statusabfragen in Folge</translation>
        </message>
        <message>
            <source>resynchronising with &lt;SYN&gt; after: %1</source>
            <translation>Neusynchronisierung mit &lt;SYN&gt; nach: %1</translation>
        </message>
        <message>
            <source>not connected (%1)</source>
            <translation>nicht verbunden (%1)</translation>
        </message>
        <message>
            <source>no transport</source>
            <translation>keine Übertragungsstrecke</translation>
        </message>
        <message>
            <source>already connecting</source>
            <translation>Verbindung wird bereits aufgebaut</translation>
        </message>
        <message>
            <source>the E-LAB board does not answer: %1</source>
            <translation>die E-LAB-Platine antwortet nicht: %1</translation>
        </message>
        <message>
            <source>nothing to send</source>
            <translation>nichts zu senden</translation>
        </message>
        <message>
            <source>not connected</source>
            <translation>nicht verbunden</translation>
        </message>
        <message>
            <source>cancelled by stop</source>
            <translation>durch Stopp abgebrochen</translation>
        </message>
        <message>
            <source>feed stream stopped</source>
            <translation>Vorschubstrom gestoppt</translation>
        </message>
        <message>
            <source>cancelled by panic stop</source>
            <translation>durch Panik-Stopp abgebrochen</translation>
        </message>
        <message>
            <source>cancelled by reset</source>
            <translation>durch Reset abgebrochen</translation>
        </message>
        <message>
            <source>reset not possible: %1</source>
            <translation>Reset nicht möglich: %1</translation>
        </message>
        <message>
            <source>no status after reset: %1</source>
            <translation>kein Status nach dem Reset: %1</translation>
        </message>
        <message>
            <source>written; the E-LAB board cannot read parameters back, nothing verified</source>
            <translation>geschrieben; die E-LAB-Platine kann Parameter nicht zurücklesen, nichts geprüft</translation>
        </message>
        <message>
            <source>unknown parameter '%1'</source>
            <translation>unbekannter Parameter '%1'</translation>
        </message>
        <message>
            <source>E-LAB cannot read parameters back, and this session has not written: %1</source>
            <translation>E-LAB kann Parameter nicht zurücklesen, und diese Sitzung hat nicht geschrieben: %1</translation>
        </message>
        <message>
            <source>E-LAB cannot read parameters back: these are the values this session last wrote</source>
            <translation>E-LAB kann Parameter nicht zurücklesen: dies sind die Werte, die diese Sitzung zuletzt geschrieben hat</translation>
        </message>
        <message>
            <source>a limit switch stopped the motion (axis %1): position unknown, reference the axis again</source>
            <translation>ein Endschalter hat die Bewegung gestoppt (Achse %1): Position unbekannt, Achse neu referenzieren</translation>
        </message>
        <message>
            <source>feed stream step %1: this machine has no axis %2</source>
            <translation>Vorschubstrom Schritt %1: diese Maschine hat keine Achse %2</translation>
        </message>
        <message>
            <source>feed stream step %1: axis %2 moves %3 steps; a single step is -1, 0 or +1</source>
            <translation>Vorschubstrom Schritt %1: Achse %2 fährt %3 Schritte; ein Einzelschritt ist -1, 0 oder +1</translation>
        </message>
        <message>
            <source>jog refused: a feed stream is running</source>
            <translation>Tippbetrieb abgelehnt: ein Vorschubstrom läuft</translation>
        </message>
        <message>
            <source>refused: a motion is running; setup and outputs are written only at standstill</source>
            <translation>abgelehnt: eine Bewegung läuft; Einstellungen und Ausgänge werden nur im Stillstand geschrieben</translation>
        </message>
        <message>
            <source>the board reports motion the host did not command (%1): stopping it</source>
            <translation>die Steuerung meldet eine Bewegung, die der Host nicht befohlen hat (%1): sie wird gestoppt</translation>
        </message>
        <message>
            <source>the limit switch of axis %1 turned active: jog stopped; only jogging away from it is allowed</source>
            <translation>der Endschalter der Achse %1 hat angesprochen: Joggen gestoppt; nur Joggen vom Schalter weg ist erlaubt</translation>
        </message>
        <message>
            <source>jog refused: axis %1 is on its limit switch; only jogging away from it (%2) is allowed</source>
            <translation>Joggen abgelehnt: Achse %1 steht auf ihrem Endschalter; nur Joggen vom Schalter weg (%2) ist erlaubt</translation>
        </message>
        <message>
            <source>stop sent, not acknowledged by the board (%1): %2</source>
            <translation>Stopp gesendet, von der Steuerung nicht bestätigt (%1): %2</translation>
        </message>
        <message>
            <source>%1; already written: %2</source>
            <translation>%1; bereits geschrieben: %2</translation>
        </message>
        <message>
            <source>jog refused: setup incomplete (tmInvSetup): %1</source>
            <translation>Tippbetrieb abgelehnt: Einrichtung unvollständig (tmInvSetup): %1</translation>
        </message>
        <message>
            <source>refused: the contour runs at %1 ticks/s, but the board's feed speed on %2 is %3: write %1 on X, Y and Z first</source>
            <translation>abgelehnt: die Kontur läuft mit %1 Takten/s, die Vorschubgeschwindigkeit der Karte auf %2 ist aber %3: zuerst %1 auf X, Y und Z schreiben</translation>
        </message>
        <message>
            <source>not known</source>
            <translation>nicht bekannt</translation>
        </message>
        <message>
            <source>refused: the contour starts with %1 at %2 steps, but it stands at %3</source>
            <translation>abgelehnt: die Kontur beginnt mit %1 bei %2 Schritten, die Achse steht aber bei %3</translation>
        </message>
        <message>
            <source>refused: the contour runs at %1 ticks/s; beside the status polls the line carries at most %2</source>
            <translation>abgelehnt: die Kontur läuft mit %1 Takten/s; neben den Statusabfragen trägt die Leitung höchstens %2</translation>
        </message>
        <message>
            <source>the stopped contour did not end with EndOfFeed</source>
            <translation>die angehaltene Kontur endete nicht mit EndOfFeed</translation>
        </message>
        <message>
            <source>the board still moved %1 ms after the stopped contour ended</source>
            <translation>die Karte bewegte sich %1 ms nach dem Ende der angehaltenen Kontur noch</translation>
        </message>
        <message>
            <source>no status after the stopped contour ended: %1</source>
            <translation>kein Status nach dem Ende der angehaltenen Kontur: %1</translation>
        </message>
        <message>
            <source>%1: ForceStopMove sent, positions unknown</source>
            <translation>%1: ForceStopMove gesendet, Positionen unbekannt</translation>
        </message>
        <message>
            <source>stop overtaken by a panic stop, a reset or a lost link</source>
            <translation>Stopp überholt von einem Panik-Stopp, einem Reset oder einer verlorenen Verbindung</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::ElabCtlJog</name>
        <message>
            <source>jog: %1</source>
            <translation>Tippbetrieb: %1</translation>
        </message>
        <message>
            <source>jog refused by the board (NAK); machine state: %1; axe state: %2</source>
            <translation>Tippbetrieb von der Platine abgelehnt (NAK); Maschinenstatus: %1; Achsstatus: %2</translation>
        </message>
        <message>
            <source>jog: %1; the board may still be jogging</source>
            <translation>Joggen: %1; die Steuerung joggt womöglich noch</translation>
        </message>
        <message>
            <source>jog not started: %1</source>
            <translation>Joggen nicht gestartet: %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::ElabCtlLine</name>
        <message>
            <source>cancelled by a stop, panic or reset</source>
            <translation>abgebrochen durch Stopp, Panik-Stopp oder Reset</translation>
        </message>
        <message>
            <source>%1 answered NAK; machine state %2: %3; axe state %4: %5</source>
            <translation>%1 mit NAK beantwortet; Maschinenstatus %2: %3; Achsstatus %4: %5</translation>
        </message>
        <message>
            <source>%1 answered NAK; the status could not be read: %2</source>
            <translation>%1 mit NAK beantwortet; der Status konnte nicht gelesen werden: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::ElabCtlMotionOps</name>
        <message>
            <source>this machine has no axis %1</source>
            <translation>diese Maschine hat keine Achse %1</translation>
        </message>
        <message>
            <source>%1 %2 for axis %3 is out of range (allowed: %4..%5)</source>
            <translation>%1 %2 für Achse %3 liegt außerhalb des Bereichs (erlaubt: %4..%5)</translation>
        </message>
        <message>
            <source>position after stop unknown: %1</source>
            <translation>Position nach dem Stopp unbekannt: %1</translation>
        </message>
        <message>
            <source>step count</source>
            <translation>Schrittzahl</translation>
        </message>
        <message>
            <source>refused: a feed stream is already running</source>
            <translation>abgelehnt: ein Vorschubstrom läuft bereits</translation>
        </message>
        <message>
            <source>%1 after %2 of %3 steps</source>
            <translation>%1 nach %2 von %3 Schritten</translation>
        </message>
        <message>
            <source>reference direction</source>
            <translation>Referenzrichtung</translation>
        </message>
        <message>
            <source>velocity</source>
            <translation>Geschwindigkeit</translation>
        </message>
        <message>
            <source>refused: axis %1 cannot reverse during a velocity move; set it to 0 and wait for standstill first</source>
            <translation>abgelehnt: Achse %1 kann während einer Geschwindigkeitsfahrt nicht umkehren; zuerst auf 0 setzen und Stillstand abwarten</translation>
        </message>
        <message>
            <source>cancelled by a stop, panic or reset</source>
            <translation>abgebrochen durch Stopp, Panik-Stopp oder Reset</translation>
        </message>
        <message>
            <source>axis %1 did not come to a standstill; the reversed velocity was not sent</source>
            <translation>Achse %1 ist nicht zum Stillstand gekommen; die umgekehrte Geschwindigkeit wurde nicht gesendet</translation>
        </message>
        <message>
            <source>no contour to run</source>
            <translation>keine Kontur zu fahren</translation>
        </message>
        <message>
            <source>contour stopped after %1 ticks: the board runs out the ticks it holds, every position stays known</source>
            <translation>Kontur nach %1 Takten angehalten: die Karte fährt die gespeicherten Takte aus, jede Position bleibt bekannt</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::ElabCtlParameters</name>
        <message>
            <source>unknown parameter '%1'</source>
            <translation>unbekannter Parameter '%1'</translation>
        </message>
        <message>
            <source>parameter set names a parameter the E-LAB board has no command for</source>
            <translation>der Parametersatz nennt einen Parameter, für den die E-LAB-Platine keinen Befehl hat</translation>
        </message>
        <message>
            <source>%1: no value for axis %2 and none written before; give all axes (X,Y,Z)</source>
            <translation>%1: kein Wert für Achse %2 und keiner zuvor geschrieben; alle Achsen angeben (X,Y,Z)</translation>
        </message>
        <message>
            <source>%1 must be below %2 (feed mode has no ramp), but %2 is not known: write %2 in the same set</source>
            <translation>%1 muss unter %2 liegen (der Vorschub hat keine Rampe), aber %2 ist unbekannt: %2 im selben Satz schreiben</translation>
        </message>
        <message>
            <source>%1 %2 on axis %3 must be below %4 %5 (feed mode has no ramp)</source>
            <translation>%1 %2 auf Achse %3 muss unter %4 %5 liegen (der Vorschub hat keine Rampe)</translation>
        </message>
        <message>
            <source>write %1, %2 and %3 first</source>
            <translation>zuerst %1, %2 und %3 schreiben</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::ElabCtlStatusMapper</name>
        <message>
            <source>refused: the emergency stop (tmPanicStop) is active</source>
            <translation>abgelehnt: der Not-Aus (tmPanicStop) ist aktiv</translation>
        </message>
        <message>
            <source>refused: a limit switch is active (%1); only jog may move the machine off it</source>
            <translation>abgelehnt: ein Endschalter ist aktiv (%1); nur im Tippbetrieb darf die Maschine davon wegfahren</translation>
        </message>
        <message>
            <source>refused: axes still moving (%1); wait until RequestAxeState reports standstill</source>
            <translation>abgelehnt: Achsen noch in Bewegung (%1); warten, bis RequestAxeState Stillstand meldet</translation>
        </message>
        <message>
            <source>jog refused: axes still moving (%1); wait until they stand still</source>
            <translation>Tippbetrieb abgelehnt: Achsen noch in Bewegung (%1); warten, bis sie stillstehen</translation>
        </message>
        <message>
            <source>refused: a limit switch is active (%1)</source>
            <translation>abgelehnt: ein Endschalter ist aktiv (%1)</translation>
        </message>
        <message>
            <source>refused: axes are moving (%1); setup and outputs are written only at standstill</source>
            <translation>abgelehnt: Achsen bewegen sich (%1); Einstellungen und Ausgänge werden nur im Stillstand geschrieben</translation>
        </message>
        <message>
            <source>refused: setup incomplete (tmInvSetup): %1</source>
            <translation>abgelehnt: Einrichtung unvollständig (tmInvSetup): %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::ElabExchangeQueue</name>
        <message>
            <source>not connected</source>
            <translation>nicht verbunden</translation>
        </message>
        <message>
            <source>unexpected reply %1 to %2 (expected %3)</source>
            <translation>unerwartete Antwort %1 auf %2 (erwartet %3)</translation>
        </message>
        <message>
            <source>no reply to %1 within %2 ms</source>
            <translation>keine Antwort auf %1 innerhalb von %2 ms</translation>
        </message>
        <message>
            <source>link restarted</source>
            <translation>Verbindung neu gestartet</translation>
        </message>
        <message>
            <source>no reply to %1 (the reply to the request behind it came)</source>
            <translation>keine Antwort auf %1 (die Antwort auf die Anfrage dahinter kam)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::elab::Presentation</name>
        <message>
            <source>The motors are powered.</source>
            <translation>Die Motoren sind bestromt.</translation>
        </message>
        <message>
            <source>The spindle motor is switched on.</source>
            <translation>Der Spindelmotor ist eingeschaltet.</translation>
        </message>
        <message>
            <source>At least one axis is moving.</source>
            <translation>Mindestens eine Achse ist in Bewegung.</translation>
        </message>
        <message>
            <source>Serial port error (documented, but never set by the firmware).</source>
            <translation>Fehler der seriellen Schnittstelle (dokumentiert, aber von der Firmware nie gesetzt).</translation>
        </message>
        <message>
            <source>Internal error (documented, but never set by the firmware).</source>
            <translation>Interner Fehler (dokumentiert, aber von der Firmware nie gesetzt).</translation>
        </message>
        <message>
            <source>Parameter error (documented, but never set by the firmware).</source>
            <translation>Parameterfehler (dokumentiert, aber von der Firmware nie gesetzt).</translation>
        </message>
        <message>
            <source>The board temperature is above 50 °C; the drivers may switch off.</source>
            <translation>Die Platinentemperatur liegt über 50 °C; die Endstufen können abschalten.</translation>
        </message>
        <message>
            <source>Setup incomplete: start speed, max speed and acceleration must all be written before moving.</source>
            <translation>Einrichtung unvollständig: Startgeschwindigkeit, Maximalgeschwindigkeit und Beschleunigung müssen vor dem Verfahren geschrieben sein.</translation>
        </message>
        <message>
            <source>A limit switch of the X axis is active.</source>
            <translation>Ein Endschalter der X-Achse ist aktiv.</translation>
        </message>
        <message>
            <source>A limit switch of the Y axis is active.</source>
            <translation>Ein Endschalter der Y-Achse ist aktiv.</translation>
        </message>
        <message>
            <source>A limit switch of the Z axis is active.</source>
            <translation>Ein Endschalter der Z-Achse ist aktiv.</translation>
        </message>
        <message>
            <source>The reference switch of the X axis is active.</source>
            <translation>Der Referenzschalter der X-Achse ist aktiv.</translation>
        </message>
        <message>
            <source>The reference switch of the Y axis is active.</source>
            <translation>Der Referenzschalter der Y-Achse ist aktiv.</translation>
        </message>
        <message>
            <source>The reference switch of the Z axis is active.</source>
            <translation>Der Referenzschalter der Z-Achse ist aktiv.</translation>
        </message>
        <message>
            <source>Emergency stop: the board's panic switch is active or the host sent ForcePanicStop.</source>
            <translation>Not-Aus: der Panik-Schalter der Platine ist aktiv oder der PC hat ForcePanicStop gesendet.</translation>
        </message>
        <message>
            <source>The X axis runs a move or feed.</source>
            <translation>Die X-Achse führt eine Fahrt oder einen Vorschub aus.</translation>
        </message>
        <message>
            <source>The X axis is jogging.</source>
            <translation>Die X-Achse ist im Tippbetrieb.</translation>
        </message>
        <message>
            <source>The Y axis runs a move or feed.</source>
            <translation>Die Y-Achse führt eine Fahrt oder einen Vorschub aus.</translation>
        </message>
        <message>
            <source>The Y axis is jogging.</source>
            <translation>Die Y-Achse ist im Tippbetrieb.</translation>
        </message>
        <message>
            <source>The Z axis runs a move or feed.</source>
            <translation>Die Z-Achse führt eine Fahrt oder einen Vorschub aus.</translation>
        </message>
        <message>
            <source>The Z axis is jogging.</source>
            <translation>Die Z-Achse ist im Tippbetrieb.</translation>
        </message>
        <message>
            <source>A limit switch is active: only jog moves are accepted.</source>
            <translation>Ein Endschalter ist aktiv: nur Fahrten im Tippbetrieb werden angenommen.</translation>
        </message>
        <message>
            <source>A reference switch is active.</source>
            <translation>Ein Referenzschalter ist aktiv.</translation>
        </message>
        <message>
            <source>Machine state (RequestMachineState)</source>
            <translation>Maschinenstatus (RequestMachineState)</translation>
        </message>
        <message>
            <source>Axis state (RequestAxeState)</source>
            <translation>Achsstatus (RequestAxeState)</translation>
        </message>
        <message>
            <source>Send raw bytes, e.g. &lt;ENQ&gt; or &lt;DC4&gt;0064,0000;0000.</source>
            <translation>Rohe Bytes senden, z. B. &lt;ENQ&gt; oder &lt;DC4&gt;0064,0000;0000.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::emis::EmisController</name>
        <message>
            <source>the SMC-IC4 did not answer %1 input polls (@IG) in a row</source>
            <translation>die SMC-IC4 hat %1 Eingangsabfragen (@IG) in Folge nicht beantwortet</translation>
        </message>
        <message>
            <source>no transport</source>
            <translation>keine Übertragungsstrecke</translation>
        </message>
        <message>
            <source>already connecting</source>
            <translation>Verbindung wird bereits aufgebaut</translation>
        </message>
        <message>
            <source>no answer from an SMC-IC4 to @V (115200 baud 8N1): %1</source>
            <translation>keine Antwort einer SMC-IC4 auf @V (115200 Baud 8N1): %1</translation>
        </message>
        <message>
            <source>not connected</source>
            <translation>nicht verbunden</translation>
        </message>
        <message>
            <source>the SMC-IC4 refused '%1' (&lt;BEL&gt;: invalid value, or the motor is still moving)</source>
            <translation>die SMC-IC4 hat '%1' abgelehnt (&lt;BEL&gt;: ungültiger Wert, oder der Motor fährt noch)</translation>
        </message>
        <message>
            <source>no reply to '%1' in time</source>
            <translation>keine Antwort auf '%1' in der vorgesehenen Zeit</translation>
        </message>
        <message>
            <source>no complete reply to '%1' in time: %2</source>
            <translation>keine vollständige Antwort auf '%1' in der vorgesehenen Zeit: %2</translation>
        </message>
        <message>
            <source>unexpected reply to '%1': %2</source>
            <translation>unerwartete Antwort auf '%1': %2</translation>
        </message>
        <message>
            <source>'%1' was cancelled (disconnect)</source>
            <translation>'%1' wurde abgebrochen (Verbindung getrennt)</translation>
        </message>
        <message>
            <source>@IG answered '%1', not eight input levels (9.2)</source>
            <translation>@IG antwortete '%1' statt acht Eingangspegeln (9.2)</translation>
        </message>
        <message>
            <source>jog refused: an input program is being written</source>
            <translation>Tippbetrieb abgelehnt: ein Eingangsprogramm wird gerade geschrieben</translation>
        </message>
        <message>
            <source>jog refused: an axis may still be moving (its arrival never came); reference it first</source>
            <translation>Tippbetrieb abgelehnt: eine Achse fährt womöglich noch (ihre Ankunft kam nie); zuerst referenzieren</translation>
        </message>
        <message>
            <source>axis %1 is still moving (its arrival &lt;DC%2&gt; has not come; the board would answer &lt;BEL&gt;)</source>
            <translation>Achse %1 fährt noch (ihre Ankunft &lt;DC%2&gt; ist nicht gekommen; die Steuerung würde mit &lt;BEL&gt; antworten)</translation>
        </message>
        <message>
            <source>axis %1 is jogging</source>
            <translation>Achse %1 ist im Tippbetrieb</translation>
        </message>
        <message>
            <source>axis %1: the arrival of its last move never came, it may still be moving; reference it first</source>
            <translation>Achse %1: die Ankunft ihrer letzten Fahrt kam nie, sie fährt womöglich noch; zuerst referenzieren</translation>
        </message>
        <message>
            <source>move of axis %1 by %2 steps is out of range (allowed: -%3..%3)</source>
            <translation>Fahrt der Achse %1 um %2 Schritte liegt außerhalb des Bereichs (erlaubt: -%3..%3)</translation>
        </message>
        <message>
            <source>absolute move refused: position of axis %1 is unknown, reference it first</source>
            <translation>Absolutfahrt abgelehnt: Position der Achse %1 ist unbekannt, zuerst referenzieren</translation>
        </message>
        <message>
            <source>target %1 of axis %2 is out of range (allowed: -%3..%3)</source>
            <translation>Ziel %1 der Achse %2 liegt außerhalb des Bereichs (erlaubt: -%3..%3)</translation>
        </message>
        <message>
            <source>move refused: %1</source>
            <translation>Fahrt abgelehnt: %1</translation>
        </message>
        <message>
            <source>move refused: an input program is being written</source>
            <translation>Fahrt abgelehnt: ein Eingangsprogramm wird gerade geschrieben</translation>
        </message>
        <message>
            <source>axis %1: the SMC-IC4 chooses the direction of its reference run itself (9.9); use 1 to reference the axis, 0 to leave it out</source>
            <translation>Achse %1: die SMC-IC4 wählt die Richtung ihrer Referenzfahrt selbst (9.9); 1 referenziert die Achse, 0 lässt sie aus</translation>
        </message>
        <message>
            <source>name at least one axis to reference</source>
            <translation>mindestens eine Achse zum Referenzieren angeben</translation>
        </message>
        <message>
            <source>reference run refused: %1</source>
            <translation>Referenzfahrt abgelehnt: %1</translation>
        </message>
        <message>
            <source>reference run refused: an input program is being written</source>
            <translation>Referenzfahrt abgelehnt: ein Eingangsprogramm wird gerade geschrieben</translation>
        </message>
        <message>
            <source>axis %1: its arrival &lt;DC%2&gt; did not come in time; it may still be moving (use the machine's emergency stop if it does); its position is unknown until it is referenced</source>
            <translation>Achse %1: ihre Ankunft &lt;DC%2&gt; kam nicht rechtzeitig; sie fährt womöglich noch (dann den Not-Halt der Maschine benutzen); ihre Position ist bis zur Referenzfahrt unbekannt</translation>
        </message>
        <message>
            <source>output '%1' does not exist (outputs 1..%2, manual 9.3)</source>
            <translation>Ausgang '%1' gibt es nicht (Ausgänge 1..%2, Handbuch 9.3)</translation>
        </message>
        <message>
            <source>unknown axis '%1' (this machine has X, Y, Z, U)</source>
            <translation>unbekannte Achse '%1' (diese Maschine hat X, Y, Z, U)</translation>
        </message>
        <message>
            <source>input '%1' does not exist (inputs 1..%2)</source>
            <translation>Eingang '%1' gibt es nicht (Eingänge 1..%2)</translation>
        </message>
        <message>
            <source>the program title must be printable ASCII of at most %1 characters (no umlauts)</source>
            <translation>der Programmtitel muss aus höchstens %1 druckbaren ASCII-Zeichen bestehen (keine Umlaute)</translation>
        </message>
        <message>
            <source>not printable ASCII</source>
            <translation>kein druckbares ASCII</translation>
        </message>
        <message>
            <source>program command %1 ('%2'): %3</source>
            <translation>Programmbefehl %1 ('%2'): %3</translation>
        </message>
        <message>
            <source>a program needs at least one command</source>
            <translation>ein Programm braucht mindestens einen Befehl</translation>
        </message>
        <message>
            <source>input %1 carries the reference switch of axis %2: a program on it can make the controller misbehave (manual 5.2.2); force it only if no switch is wired there</source>
            <translation>an Eingang %1 liegt der Referenzschalter der Achse %2: ein Programm darauf kann zu Fehlverhalten der Steuerung führen (Handbuch 5.2.2); nur erzwingen, wenn dort kein Schalter angeschlossen ist</translation>
        </message>
        <message>
            <source>input programs are written while every axis stands still</source>
            <translation>Eingangsprogramme werden geschrieben, während alle Achsen stillstehen</translation>
        </message>
        <message>
            <source>the partial program was erased (*PEIN%1)</source>
            <translation>das unvollständige Programm wurde gelöscht (*PEIN%1)</translation>
        </message>
        <message>
            <source>erasing the partial program (*PEIN%1) failed too: check the input before using it</source>
            <translation>das Löschen des unvollständigen Programms (*PEIN%1) ist ebenfalls fehlgeschlagen: den Eingang vor der Benutzung prüfen</translation>
        </message>
        <message>
            <source>program for input %1 not stored: %2; %3</source>
            <translation>Programm für Eingang %1 nicht gespeichert: %2; %3</translation>
        </message>
        <message>
            <source>the console sends one SMC-IC4 command at a time</source>
            <translation>die Konsole sendet jeweils einen SMC-IC4-Befehl</translation>
        </message>
        <message>
            <source>input programs are written with the program editor, not the console</source>
            <translation>Eingangsprogramme werden mit dem Programmeditor geschrieben, nicht mit der Konsole</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message numerus="yes">
            <source> (%n command(s) before it were accepted)</source>
            <translation>
                <numerusform> (%n Befehl davor wurde angenommen)</numerusform>
                <numerusform> (%n Befehle davor wurden angenommen)</numerusform>
            </translation>
        </message>
        <message>
            <source>parameters are written while every axis stands still</source>
            <translation>Parameter werden geschrieben, während alle Achsen stillstehen</translation>
        </message>
        <message>
            <source>unknown parameter '%1'</source>
            <translation>unbekannter Parameter '%1'</translation>
        </message>
        <message>
            <source>%1 cannot be read back: the SMC-IC4 reports no working values (only the stored system parameters, *PRSYS)</source>
            <translation>%1 kann nicht zurückgelesen werden: die SMC-IC4 meldet keine Arbeitswerte (nur die gespeicherten Systemparameter, *PRSYS)</translation>
        </message>
        <message>
            <source>no parameters to store</source>
            <translation>keine Parameter zum Speichern</translation>
        </message>
        <message>
            <source>system parameters are stored while every axis stands still</source>
            <translation>Systemparameter werden gespeichert, während alle Achsen stillstehen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::emis::EmisLink</name>
        <message>
            <source>the link is not open</source>
            <translation>die Verbindung ist nicht offen</translation>
        </message>
        <message>
            <source>garbage on the line: %1</source>
            <translation>unlesbare Daten auf der Leitung: %1</translation>
        </message>
        <message>
            <source>reply nobody waited for: '%1' (late, or sent by the board by itself)</source>
            <translation>Antwort, auf die niemand wartete: '%1' (verspätet, oder von der Steuerung selbst gesendet)</translation>
        </message>
        <message>
            <source>&lt;NAK&gt; instead of &lt;ACK&gt;</source>
            <translation>&lt;NAK&gt; statt &lt;ACK&gt;</translation>
        </message>
        <message>
            <source>&lt;ACK&gt; instead of &lt;NAK&gt;</source>
            <translation>&lt;ACK&gt; statt &lt;NAK&gt;</translation>
        </message>
        <message>
            <source>&lt;NAK&gt; while storing</source>
            <translation>&lt;NAK&gt; beim Speichern</translation>
        </message>
        <message>
            <source>'%1' where "Ready!" was expected</source>
            <translation>'%1', wo "Ready!" erwartet war</translation>
        </message>
        <message>
            <source>no "Ready!" after the first &lt;ACK&gt;</source>
            <translation>kein "Ready!" nach dem ersten &lt;ACK&gt;</translation>
        </message>
        <message>
            <source>%1 of %2 entries acknowledged after "Ready!"</source>
            <translation>%1 von %2 Einträgen nach "Ready!" quittiert</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::emis::Grammar</name>
        <message>
            <source>'%1' is malformed (see the SMC-IC4 manual, chapter 9)</source>
            <translation>'%1' ist fehlerhaft (siehe SMC-IC4-Handbuch, Kapitel 9)</translation>
        </message>
        <message>
            <source>'%1' names axis %2 twice</source>
            <translation>'%1' nennt Achse %2 zweimal</translation>
        </message>
        <message>
            <source>unknown command '%1'</source>
            <translation>unbekannter Befehl '%1'</translation>
        </message>
        <message>
            <source>%1: value %2 is out of range (allowed: %3..%4)</source>
            <translation>%1: Wert %2 liegt außerhalb des Bereichs (erlaubt: %3..%4)</translation>
        </message>
        <message>
            <source>%1: %2 is not a step resolution (1, 2, 4, ..., 256)</source>
            <translation>%1: %2 ist keine Schrittauflösung (1, 2, 4, ..., 256)</translation>
        </message>
        <message>
            <source>text before &lt;ETX&gt;: '%1'</source>
            <translation>Text vor &lt;ETX&gt;: '%1'</translation>
        </message>
        <message>
            <source>a command holds printable ASCII characters only</source>
            <translation>ein Befehl enthält nur druckbare ASCII-Zeichen</translation>
        </message>
        <message>
            <source>empty command</source>
            <translation>leerer Befehl</translation>
        </message>
        <message>
            <source>a program header ends with &lt;STX&gt;, not &lt;CR&gt;</source>
            <translation>ein Programmkopf endet mit &lt;STX&gt;, nicht mit &lt;CR&gt;</translation>
        </message>
        <message>
            <source>program title longer than %1 characters</source>
            <translation>Programmtitel länger als %1 Zeichen</translation>
        </message>
        <message>
            <source>'%1' cannot be part of an input program: queries, system parameters and program commands are not stored</source>
            <translation>'%1' kann nicht Teil eines Eingangsprogramms sein: Abfragen, Systemparameter und Programmbefehle werden nicht gespeichert</translation>
        </message>
        <message>
            <source>system parameter '%1' is malformed (see the manual, 9.14)</source>
            <translation>Systemparameter '%1' ist fehlerhaft (siehe Handbuch, 9.14)</translation>
        </message>
        <message>
            <source>unknown system parameter '%1' (9.14 knows D, c, REFSW, S, E, E9, R)</source>
            <translation>unbekannter Systemparameter '%1' (9.14 kennt D, c, REFSW, S, E, E9, R)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::emis::ParameterPlan</name>
        <message>
            <source>%1 of axis %2 needs %3 in the same set: the SMC-IC4 sets run and idle current with one command (c,x100,20, manual 9.8) and the value of %3 is not known</source>
            <translation>%1 der Achse %2 braucht %3 im selben Satz: die SMC-IC4 setzt Arbeits- und Ruhestrom mit einem Befehl (c,x100,20, Handbuch 9.8), und der Wert von %3 ist nicht bekannt</translation>
        </message>
        <message>
            <source>%1 cannot be stored: the SMC-IC4 has no system parameter for it (manual 9.14); use set</source>
            <translation>%1 kann nicht gespeichert werden: die SMC-IC4 hat dafür keinen Systemparameter (Handbuch 9.14); set verwenden</translation>
        </message>
        <message>
            <source>an SMCflex compatibility entry is stored (%1); store --clear (*PESYS) erases it</source>
            <translation>ein Eintrag für SMCflex-Kompatibilität ist gespeichert (%1); store --clear (*PESYS) löscht ihn</translation>
        </message>
        <message>
            <source>not understood in the *PRSYS answer: %1</source>
            <translation>in der *PRSYS-Antwort nicht verstanden: %1</translation>
        </message>
        <message>
            <source>%1 is stored per motor (%2); %3 is the first</source>
            <translation>%1 ist je Motor gespeichert (%2); %3 ist der erste Wert</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::emis::Presentation</name>
        <message>
            <source>unknown control name at column %1 (known: &lt;CR&gt; &lt;STX&gt; &lt;ETX&gt; &lt;xNN&gt;)</source>
            <translation>unbekannter Steuerzeichenname in Spalte %1 (bekannt: &lt;CR&gt; &lt;STX&gt; &lt;ETX&gt; &lt;xNN&gt;)</translation>
        </message>
        <message>
            <source>non-ASCII character at column %1</source>
            <translation>Nicht-ASCII-Zeichen in Spalte %1</translation>
        </message>
        <message>
            <source>Inputs (@IG, 9.2)</source>
            <translation>Eingänge (@IG, 9.2)</translation>
        </message>
        <message>
            <source>Input %1: reference switch of axis %2 (or a free input when no switch is wired).</source>
            <translation>Eingang %1: Referenzschalter der Achse %2 (oder ein freier Eingang, wenn kein Schalter angeschlossen ist).</translation>
        </message>
        <message>
            <source>Input %1: free input.</source>
            <translation>Eingang %1: freier Eingang.</translation>
        </message>
        <message>
            <source>not printable ASCII</source>
            <translation>kein druckbares ASCII</translation>
        </message>
        <message>
            <source>no stop command: a button on the reset input (manual 5.8) or the machine's emergency stop stops it; positions are then unknown until referenced</source>
            <translation>kein Stopp-Befehl: ein Taster am Reset-Eingang (Handbuch 5.8) oder der Not-Halt der Maschine hält sie an; die Positionen sind danach bis zur Referenzfahrt unbekannt</translation>
        </message>
        <message>
            <source>A move only ends when it arrives. A reset (a normally open button on the board's reset input) stops every motor at once and restarts the board with its stored values. StepDeck sees it when a move's arrival does not come (that axis: motion unconfirmed, position unknown) or when the board does not answer while it restarts; either way every axis then counts as not referenced and the outputs as unknown. A reset it could not see leaves the positions it shows: reference the axes after every reset.</source>
            <translation>Eine Fahrt endet erst, wenn sie ihr Ziel erreicht. Ein Reset (ein Schließer am Reset-Eingang der Steuerung) hält alle Motoren sofort an und startet die Steuerung mit ihren gespeicherten Werten neu. StepDeck bemerkt ihn, wenn die Ankunftsmeldung einer Fahrt ausbleibt (diese Achse: Bewegung unbestätigt, Position unbekannt) oder die Steuerung während des Neustarts nicht antwortet; in beiden Fällen gilt danach jede Achse als nicht referenziert und die Ausgänge als unbekannt. Nach einem Reset, den StepDeck nicht bemerken konnte, bleiben die angezeigten Positionen stehen: nach jedem Reset die Achsen referenzieren.</translation>
        </message>
        <message>
            <source>Send a command, e.g. @V (firmware version) or @IG (inputs); the final &lt;CR&gt; is added.</source>
            <translation>Befehl senden, z. B. @V (Firmware-Version) oder @IG (Eingänge); das abschließende &lt;CR&gt; wird angehängt.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::emis::ReplyDecoder</name>
        <message numerus="yes">
            <source>%n byte(s) that are neither text nor a reply terminator</source>
            <translation>
                <numerusform>%n Byte, das weder Text noch ein Antwortende ist</numerusform>
                <numerusform>%n Bytes, die weder Text noch ein Antwortende sind</numerusform>
            </translation>
        </message>
        <message>
            <source>reply text longer than %1 bytes without a terminator</source>
            <translation>Antworttext länger als %1 Bytes ohne Abschlusszeichen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::laser::LaserAxisController</name>
        <message>
            <source>the port did not take the bytes in time</source>
            <translation>der Port hat die Bytes nicht rechtzeitig übernommen</translation>
        </message>
        <message>
            <source>no transport</source>
            <translation>keine Übertragungsstrecke</translation>
        </message>
        <message>
            <source>already connecting</source>
            <translation>Verbindung wird bereits aufgebaut</translation>
        </message>
        <message>
            <source>no longer tracking axis %1 on its way to a target: the protocol has no stop command; it goes on unless the machine's emergency stop is used</source>
            <translation>Achse %1 wird auf dem Weg zu ihrem Ziel nicht mehr verfolgt: das Protokoll hat keinen Stoppbefehl; sie fährt weiter, außer der Not-Halt der Maschine wird benutzt</translation>
        </message>
        <message>
            <source>not connected</source>
            <translation>nicht verbunden</translation>
        </message>
        <message>
            <source>malformed status frame from the axes ignored (%1): %2</source>
            <translation>fehlerhafte Statusmeldung der Achsen ignoriert (%1): %2</translation>
        </message>
        <message>
            <source>the laser motor-axis protocol has no parameters: it only knows home and move to position</source>
            <translation>das Motorachsen-Protokoll des Lasers hat keine Parameter: es kennt nur Referenzfahrt und Fahrt auf Position</translation>
        </message>
        <message>
            <source>jog refused: the laser motor axes have no jog command; jog moves them by short targets, one after the other</source>
            <translation>Tippbetrieb abgelehnt: die Motorachsen des Lasers haben keinen Tippbefehl; der Tippbetrieb fährt sie in kurzen Zielen, eines nach dem anderen</translation>
        </message>
        <message>
            <source>this machine has no axis %1</source>
            <translation>diese Maschine hat keine Achse %1</translation>
        </message>
        <message>
            <source>target %1 for axis %2 is out of range (allowed: 0..%3)</source>
            <translation>Ziel %1 für Achse %2 liegt außerhalb des Bereichs (erlaubt: 0..%3)</translation>
        </message>
        <message>
            <source>relative move refused: the position of axis %1 is unknown (no status frame from it in this session); home it or move it to an absolute target first</source>
            <translation>Relativfahrt abgelehnt: die Position von Achse %1 ist unbekannt (in dieser Sitzung keine Statusmeldung von ihr); zuerst Referenzfahrt oder Fahrt auf ein absolutes Ziel</translation>
        </message>
        <message>
            <source>no axis to home: every direction is 0</source>
            <translation>keine Achse zu referenzieren: jede Richtung ist 0</translation>
        </message>
        <message>
            <source>replaced by a newer target for axis %1</source>
            <translation>durch ein neueres Ziel für Achse %1 ersetzt</translation>
        </message>
        <message>
            <source>axis %1 stopped at its end switch at %2 before reaching %3</source>
            <translation>Achse %1 hat an ihrem Endschalter bei %2 angehalten, bevor sie %3 erreichte</translation>
        </message>
        <message>
            <source>axis %1 did not report reaching its target %2 within %3 s; it may still be moving</source>
            <translation>Achse %1 hat das Erreichen ihres Ziels %2 nicht innerhalb von %3 s gemeldet; sie fährt möglicherweise noch</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::laser::LaserCodec</name>
        <message>
            <source>no error</source>
            <translation>kein Fehler</translation>
        </message>
        <message>
            <source>wrong length (a frame is 7 digits and CR)</source>
            <translation>falsche Länge (ein Rahmen ist 7 Ziffern und CR)</translation>
        </message>
        <message>
            <source>too long (more than 7 characters before the CR)</source>
            <translation>zu lang (mehr als 7 Zeichen vor dem CR)</translation>
        </message>
        <message>
            <source>a character that is not a digit</source>
            <translation>ein Zeichen, das keine Ziffer ist</translation>
        </message>
        <message>
            <source>unknown axis (only 1, 2 and 3 exist)</source>
            <translation>unbekannte Achse (nur 1, 2 und 3 gibt es)</translation>
        </message>
        <message>
            <source>unknown command (only 1 home and 2 move)</source>
            <translation>unbekannter Befehl (nur 1 Referenzfahrt und 2 Fahrt)</translation>
        </message>
        <message>
            <source>unknown status (only 0 to 4)</source>
            <translation>unbekannter Status (nur 0 bis 4)</translation>
        </message>
        <message>
            <source>home %1</source>
            <translation>Referenzfahrt %1</translation>
        </message>
        <message>
            <source>move %1 to %2</source>
            <translation>%1 auf %2 fahren</translation>
        </message>
        <message>
            <source>target reached</source>
            <translation>Ziel erreicht</translation>
        </message>
        <message>
            <source>end switch</source>
            <translation>Endschalter</translation>
        </message>
        <message>
            <source>home switch</source>
            <translation>Referenzschalter</translation>
        </message>
        <message>
            <source>door opened</source>
            <translation>Tür geöffnet</translation>
        </message>
        <message>
            <source>door closed</source>
            <translation>Tür geschlossen</translation>
        </message>
        <message>
            <source>%1 at %2: %3</source>
            <translation>%1 bei %2: %3</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::machine::Machine</name>
        <message>
            <source>controller "%1": %2</source>
            <translation>Steuerung "%1": %2</translation>
        </message>
        <message>
            <source>the machine was closed</source>
            <translation>die Maschine wurde geschlossen</translation>
        </message>
        <message>
            <source>controller "%1" lost its link (%2): the other controllers were told to stop</source>
            <translation>Steuerung "%1" hat die Verbindung verloren (%2): Die anderen Steuerungen wurden angehalten</translation>
        </message>
        <message>
            <source>the machine has no axis %1</source>
            <translation>die Maschine hat keine Achse %1</translation>
        </message>
        <message>
            <source>%1: controller "%2" is not connected</source>
            <translation>%1: Steuerung "%2" ist nicht verbunden</translation>
        </message>
        <message>
            <source>%1: the jog rate is not a finite number</source>
            <translation>%1: Die Tippgeschwindigkeit ist keine endliche Zahl</translation>
        </message>
        <message>
            <source>no axis to move</source>
            <translation>keine Achse zu fahren</translation>
        </message>
        <message>
            <source>%1: the target is not a finite number</source>
            <translation>%1: Das Ziel ist keine endliche Zahl</translation>
        </message>
        <message>
            <source>%1 is not referenced: its position is unknown, so an absolute move could go anywhere</source>
            <translation>%1 ist nicht referenziert: Seine Position ist unbekannt, eine absolute Fahrt könnte überallhin gehen</translation>
        </message>
        <message>
            <source>%1 %2 %3 is outside the soft limits %4..%5</source>
            <translation>%1 %2 %3 liegt außerhalb der Software-Endlagen %4..%5</translation>
        </message>
        <message>
            <source>the move ended before its target: %1</source>
            <translation>die Fahrt endete vor ihrem Ziel: %1</translation>
        </message>
        <message>
            <source>%1 is on its limit switch</source>
            <translation>%1 steht auf ihrem Endschalter</translation>
        </message>
        <message>
            <source>%1 stands at %2 %3, not at %4</source>
            <translation>%1 steht bei %2 %3, nicht bei %4</translation>
        </message>
        <message>
            <source>referencing stopped</source>
            <translation>Referenzieren angehalten</translation>
        </message>
        <message>
            <source>referencing stopped by the panic stop</source>
            <translation>Referenzieren durch den Not-Halt angehalten</translation>
        </message>
        <message>
            <source>a reference run is going already</source>
            <translation>eine Referenzfahrt läuft bereits</translation>
        </message>
        <message>
            <source>axis %1 is named twice</source>
            <translation>Achse %1 ist zweimal genannt</translation>
        </message>
        <message>
            <source>%1: controller "%2" has no reference run</source>
            <translation>%1: Steuerung "%2" hat keine Referenzfahrt</translation>
        </message>
        <message>
            <source>no axis to reference</source>
            <translation>keine Achse zu referenzieren</translation>
        </message>
        <message>
            <source>controller "%1" is not connected: referencing stopped</source>
            <translation>Steuerung "%1" ist nicht verbunden: Referenzieren angehalten</translation>
        </message>
        <message>
            <source>controller "%1": referencing failed: %2</source>
            <translation>Steuerung "%1": Referenzieren fehlgeschlagen: %2</translation>
        </message>
        <message>
            <source>controller "%1": the reference run ended before the reference switch was reached</source>
            <translation>Steuerung "%1": die Referenzfahrt endete, bevor der Referenzschalter erreicht war</translation>
        </message>
        <message>
            <source>%1 stopped at its end switch</source>
            <translation>%1 hielt an ihrem Endschalter an</translation>
        </message>
        <message>
            <source>%1: controller "%2" takes no feed rate</source>
            <translation>%1: Steuerung „%2“ nimmt keinen Vorschub an</translation>
        </message>
        <message>
            <source>controller "%1" did not confirm spindle and coolant off within %2 s: switch them off at the machine</source>
            <translation>Steuerung "%1" hat Spindel und Kühlmittel aus nicht innerhalb von %2 s bestätigt: an der Maschine ausschalten</translation>
        </message>
        <message>
            <source>controller "%1" did not switch the %2 off (%3): switch it off at the machine</source>
            <translation>Steuerung "%1" hat %2 nicht ausgeschaltet (%3): an der Maschine ausschalten</translation>
        </message>
        <message>
            <source>spindle</source>
            <translation>die Spindel</translation>
        </message>
        <message>
            <source>coolant</source>
            <translation>das Kühlmittel</translation>
        </message>
        <message>
            <source>controller "%1" lost its link before it switched spindle and coolant off: switch them off at the machine</source>
            <translation>Steuerung "%1" verlor die Verbindung, bevor sie Spindel und Kühlmittel ausschaltete: an der Maschine ausschalten</translation>
        </message>
        <message>
            <source>spindle and coolant switched off</source>
            <translation>Spindel und Kühlmittel ausgeschaltet</translation>
        </message>
        <message>
            <source>a reference run is under way</source>
            <translation>eine Referenzfahrt läuft</translation>
        </message>
        <message>
            <source>%1: the machine moves for it alone until it ends or holds</source>
            <translation>%1: Bis zu dessen Ende oder Halt bewegt sich die Maschine nur dafür</translation>
        </message>
        <message>
            <source>the axes are being jogged</source>
            <translation>die Achsen werden im Tippbetrieb verfahren</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::machine::MachineFile</name>
        <message>
            <source>unknown key (known: %1)</source>
            <translation>unbekannter Schlüssel (bekannt: %1)</translation>
        </message>
        <message>
            <source>unknown key (did you mean %1?)</source>
            <translation>unbekannter Schlüssel (meinten Sie %1?)</translation>
        </message>
        <message>
            <source>missing</source>
            <translation>fehlt</translation>
        </message>
        <message>
            <source>must be a text in quotes</source>
            <translation>muss ein Text in Anführungszeichen sein</translation>
        </message>
        <message>
            <source>must be a decimal number</source>
            <translation>muss eine Dezimalzahl sein</translation>
        </message>
        <message>
            <source>must be "stepdeck-machine"</source>
            <translation>muss "stepdeck-machine" sein</translation>
        </message>
        <message>
            <source>must be a list of controllers</source>
            <translation>muss eine Liste von Steuerungen sein</translation>
        </message>
        <message>
            <source>must be a list of axes</source>
            <translation>muss eine Liste von Achsen sein</translation>
        </message>
        <message>
            <source>must be an object {"id", "model", "port", …}</source>
            <translation>muss ein Objekt {"id", "model", "port", …} sein</translation>
        </message>
        <message>
            <source>must be "rts" or "dtr"</source>
            <translation>muss "rts" oder "dtr" sein</translation>
        </message>
        <message>
            <source>must map controller axes to bus addresses, e.g. {"X": 1, "Y": 2}</source>
            <translation>muss Steuerungsachsen Busadressen zuordnen, z. B. {"X": 1, "Y": 2}</translation>
        </message>
        <message>
            <source>not a controller axis (X, Y, Z or U)</source>
            <translation>keine Steuerungsachse (X, Y, Z oder U)</translation>
        </message>
        <message>
            <source>must be a whole bus address</source>
            <translation>muss eine ganzzahlige Busadresse sein</translation>
        </message>
        <message>
            <source>must be an object {"name", "controller", "axis", "unit", …}</source>
            <translation>muss ein Objekt {"name", "controller", "axis", "unit", …} sein</translation>
        </message>
        <message>
            <source>must be "mm", "deg" or "steps"</source>
            <translation>muss "mm", "deg" oder "steps" sein</translation>
        </message>
        <message>
            <source>must be true or false</source>
            <translation>muss true oder false sein</translation>
        </message>
        <message>
            <source>must be [minimum, maximum] in the axis' unit</source>
            <translation>muss [Minimum, Maximum] in der Einheit der Achse sein</translation>
        </message>
        <message>
            <source>must be an object {"direction", "order"}</source>
            <translation>muss ein Objekt {"direction", "order"} sein</translation>
        </message>
        <message>
            <source>must be -1 or 1</source>
            <translation>muss -1 oder 1 sein</translation>
        </message>
        <message>
            <source>must be a whole number</source>
            <translation>muss eine ganze Zahl sein</translation>
        </message>
        <message>
            <source>line %1, column %2: %3</source>
            <translation>Zeile %1, Spalte %2: %3</translation>
        </message>
        <message>
            <source>the file is empty: a machine file holds a JSON object with "format": "stepdeck-machine"</source>
            <translation>die Datei ist leer: Eine Maschinendatei enthält ein JSON-Objekt mit "format": "stepdeck-machine"</translation>
        </message>
        <message>
            <source>not a machine file: it holds no JSON object</source>
            <translation>keine Maschinendatei: Sie enthält kein JSON-Objekt</translation>
        </message>
        <message>
            <source>cannot open %1: %2</source>
            <translation>%1 kann nicht geöffnet werden: %2</translation>
        </message>
        <message>
            <source>cannot write %1: %2</source>
            <translation>%1 kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>the machine needs at least one controller</source>
            <translation>die Maschine braucht mindestens eine Steuerung</translation>
        </message>
        <message>
            <source>"%1" is used by another controller</source>
            <translation>"%1" wird schon von einer anderen Steuerung verwendet</translation>
        </message>
        <message>
            <source>must be a short name: a letter, then letters, digits, _ or - (at most 24)</source>
            <translation>muss ein kurzer Name sein: ein Buchstabe, dann Buchstaben, Ziffern, _ oder - (höchstens 24)</translation>
        </message>
        <message>
            <source>must name a serial port, tcp://HOST:PORT or "sim"</source>
            <translation>muss eine serielle Schnittstelle, tcp://HOST:PORT oder "sim" nennen</translation>
        </message>
        <message>
            <source>%1 has no reset line</source>
            <translation>%1 hat keine Reset-Leitung</translation>
        </message>
        <message>
            <source>%1 has no drives on a bus: leave "axes" out</source>
            <translation>%1 hat keine Antriebe an einem Bus: "axes" weglassen</translation>
        </message>
        <message>
            <source>bus address %1 is outside %2..%3</source>
            <translation>Busadresse %1 liegt außerhalb von %2..%3</translation>
        </message>
        <message>
            <source>bus address %1 is given to two axes</source>
            <translation>Busadresse %1 ist zwei Achsen zugeordnet</translation>
        </message>
        <message>
            <source>the machine needs at least one axis</source>
            <translation>die Maschine braucht mindestens eine Achse</translation>
        </message>
        <message>
            <source>must be one of %1</source>
            <translation>muss eines von %1 sein</translation>
        </message>
        <message>
            <source>%1 is used by another axis</source>
            <translation>%1 wird schon von einer anderen Achse verwendet</translation>
        </message>
        <message>
            <source>no controller "%1" (controllers: %2)</source>
            <translation>keine Steuerung "%1" (Steuerungen: %2)</translation>
        </message>
        <message>
            <source>no controller "%1" (did you mean %2?)</source>
            <translation>keine Steuerung "%1" (meinten Sie %2?)</translation>
        </message>
        <message>
            <source>controller "%1" has no axis %2 (it has %3)</source>
            <translation>Steuerung "%1" hat keine Achse %2 (sie hat %3)</translation>
        </message>
        <message>
            <source>axis %1 of controller "%2" already drives another axis</source>
            <translation>Achse %1 der Steuerung "%2" treibt schon eine andere Achse an</translation>
        </message>
        <message>
            <source>must be a decimal greater than 0 (is %1)</source>
            <translation>muss eine Dezimalzahl größer als 0 sein (ist %1)</translation>
        </message>
        <message>
            <source>must be 1 for an axis counted in steps</source>
            <translation>muss für eine in Schritten gezählte Achse 1 sein</translation>
        </message>
        <message>
            <source>the minimum must be below the maximum</source>
            <translation>das Minimum muss kleiner als das Maximum sein</translation>
        </message>
        <message>
            <source>must be a speed greater than 0 in %1/s</source>
            <translation>muss eine Geschwindigkeit größer als 0 in %1/s sein</translation>
        </message>
        <message>
            <source>%1 %2/s is %3 steps/s, above the %4 steps/s %5 can jog</source>
            <translation>%1 %2/s sind %3 Schritte/s, mehr als die %4 Schritte/s, die %5 tippen kann</translation>
        </message>
        <message>
            <source>%1 chooses the direction of its reference runs itself: leave "direction" out</source>
            <translation>%1 wählt die Richtung seiner Referenzfahrten selbst: "direction" weglassen</translation>
        </message>
        <message>
            <source>must be a whole number from 0 to 99</source>
            <translation>muss eine ganze Zahl von 0 bis 99 sein</translation>
        </message>
        <message>
            <source>the machine needs a name</source>
            <translation>die Maschine braucht einen Namen</translation>
        </message>
        <message>
            <source>must be an acceleration greater than 0 in %1/s² (is %2)</source>
            <translation>muss eine Beschleunigung größer als 0 in %1/s² sein (ist %2)</translation>
        </message>
        <message>
            <source>unknown model</source>
            <translation>unbekanntes Modell</translation>
        </message>
        <message>
            <source>%1 holds no parameter</source>
            <translation>%1 enthält keinen Parameter</translation>
        </message>
        <message>
            <source>must be an object {"maxRpm": 24000}</source>
            <translation>muss ein Objekt {"maxRpm": 24000} sein</translation>
        </message>
        <message>
            <source>must be a speed greater than 0 in rpm (is %1)</source>
            <translation>muss eine Drehzahl größer als 0 in U/min sein (ist %1)</translation>
        </message>
        <message>
            <source>no controller of this machine switches a spindle: leave "spindle" out</source>
            <translation>keine Steuerung dieser Maschine schaltet eine Spindel: "spindle" weglassen</translation>
        </message>
        <message>
            <source>must be 1 or 2 (the versions this StepDeck reads)</source>
            <translation>muss 1 oder 2 sein (die Versionen, die dieses StepDeck liest)</translation>
        </message>
        <message>
            <source>must list the controller's axes, e.g. [{"name": "X", "address": 1}]</source>
            <translation>muss die Achsen der Steuerung auflisten, z. B. [{"name": "X", "address": 1}]</translation>
        </message>
        <message>
            <source>must be an object {"name", "address"}</source>
            <translation>muss ein Objekt {"name", "address"} sein</translation>
        </message>
        <message>
            <source>must be X, Y, Z, U or a letter and then letters, digits or _ (2 to 32 characters)</source>
            <translation>muss X, Y, Z, U oder ein Buchstabe, dann Buchstaben, Ziffern oder _ sein (2 bis 32 Zeichen)</translation>
        </message>
        <message>
            <source>not an axis of its controller (X, Y, Z, U, axis5 … or a name the controller gives)</source>
            <translation>keine Achse ihrer Steuerung (X, Y, Z, U, axis5 … oder ein Name, den die Steuerung vergibt)</translation>
        </message>
        <message>
            <source>must be "clamp" (run a feed or S above the machine's highest at that highest, the default) or "refuse" (refuse it in the check)</source>
            <translation>muss "clamp" (ein Vorschub oder S über dem Höchsten der Maschine läuft mit diesem Höchsten, Vorgabe) oder "refuse" (die Prüfung weist ihn ab) sein</translation>
        </message>
        <message>
            <source>must be "table" (G43 takes the tool table's lengths, the default) or "touchOff" (Z is touched off after each tool change)</source>
            <translation>muss "table" (G43 nimmt die Längen der Werkzeugtabelle, Vorgabe) oder "touchOff" (Z wird nach jedem Werkzeugwechsel angetastet) sein</translation>
        </message>
        <message>
            <source>must be true (the spindle output drives a laser) or false</source>
            <translation>muss true (der Spindelausgang steuert einen Laser) oder false sein</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::machine::MachineSetup</name>
        <message numerus="yes">
            <source>controller "%1": wrote its setup from %2 (%n parameter(s))</source>
            <translation>
                <numerusform>Steuerung „%1“: Einrichtung aus %2 geschrieben (%n Parameter)</numerusform>
                <numerusform>Steuerung „%1“: Einrichtung aus %2 geschrieben (%n Parameter)</numerusform>
            </translation>
        </message>
        <message>
            <source>controller "%1": writing its setup from %2 failed: %3</source>
            <translation>Steuerung „%1“: Schreiben der Einrichtung aus %2 fehlgeschlagen: %3</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::motion::CanonicalMove</name>
        <message>
            <source>a move over %1 axes (1..%2)</source>
            <translation>eine Bewegung über %1 Achsen (1..%2)</translation>
        </message>
        <message>
            <source>a move to a position that is not a number</source>
            <translation>eine Bewegung zu einer Position, die keine Zahl ist</translation>
        </message>
        <message>
            <source>a feed move without a feed rate</source>
            <translation>eine Vorschubbewegung ohne Vorschub</translation>
        </message>
        <message>
            <source>an arc without its centre</source>
            <translation>ein Bogen ohne seinen Mittelpunkt</translation>
        </message>
        <message>
            <source>an arc whose geometry is not valid</source>
            <translation>ein Bogen mit ungültiger Geometrie</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::motion::ContourSteps</name>
        <message>
            <source>the contour is closed: no move follows its end</source>
            <translation>die Kontur ist abgeschlossen: nach ihrem Ende folgt keine Bewegung</translation>
        </message>
        <message>
            <source>the contour's queue is full (%1 moves)</source>
            <translation>die Warteschlange der Kontur ist voll (%1 Bewegungen)</translation>
        </message>
        <message>
            <source>a rapid is not part of a contour: the stream ends before it</source>
            <translation>ein Eilgang gehört nicht zu einer Kontur: der Strom endet davor</translation>
        </message>
        <message>
            <source>a move over %1 axes in a stream of %2</source>
            <translation>eine Bewegung über %1 Achsen in einem Strom über %2</translation>
        </message>
        <message>
            <source>line %1 does not start where the contour stands (axis %2: %3, not %4)</source>
            <translation>Zeile %1 beginnt nicht dort, wo die Kontur steht (Achse %2: %3, nicht %4)</translation>
        </message>
        <message>
            <source>line %1: its feed needs %2 ticks/s, the stream runs %3 (highest feed %4 unit/s)</source>
            <translation>Zeile %1: ihr Vorschub braucht %2 Takte/s, der Strom läuft mit %3 (höchster Vorschub %4 Einheiten/s)</translation>
        </message>
        <message>
            <source>line %1 would take axis %2 to %3 steps, beyond its soft limit %4: the contour ends before it</source>
            <translation>Zeile %1 würde Achse %2 auf %3 Schritte bringen, jenseits ihres Software-Endschalters %4: die Kontur endet davor</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::motion::MoveExecutor</name>
        <message>
            <source>%1: controller "%2" has no reference run (G28)</source>
            <translation>%1: Steuerung "%2" hat keine Referenzfahrt (G28)</translation>
        </message>
        <message>
            <source>controller "%1": its fast speed is no longer known, so G0 would run at the last F; the program stops here</source>
            <translation>Steuerung "%1": Ihre Eilganggeschwindigkeit ist nicht mehr bekannt, G0 liefe also mit dem letzten F; das Programm hält hier an</translation>
        </message>
        <message>
            <source>controller "%1": %2</source>
            <translation>Steuerung „%1“: %2</translation>
        </message>
        <message>
            <source>%1: controller "%2" moves to targets only, so a relative move (G91) needs the axis' position: home it (G28 %1) or move it to an absolute target first</source>
            <translation>%1: Steuerung "%2" fährt nur Ziele an, eine relative Bewegung (G91) braucht daher die Position der Achse: sie zuerst referenzieren (G28 %1) oder auf ein absolutes Ziel fahren</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::motion::StreamExecutor</name>
        <message>
            <source>a contour's steps run at one tick rate below %1 on every axis, and %1 is not known: write the controller's setup first</source>
            <translation>die Schritte einer Kontur laufen mit einem Takt unterhalb von %1 auf jeder Achse, und %1 ist nicht bekannt: zuerst die Einrichtung der Steuerung schreiben</translation>
        </message>
        <message>
            <source>%1 is too low for a contour's tick (at least 2 steps/s on every axis)</source>
            <translation>%1 ist zu niedrig für den Takt einer Kontur (mindestens 2 Schritte/s auf jeder Achse)</translation>
        </message>
        <message>
            <source>the contour has ended</source>
            <translation>die Kontur ist beendet</translation>
        </message>
        <message>
            <source>cancelled before the contour was given</source>
            <translation>abgebrochen, bevor die Kontur übergeben wurde</translation>
        </message>
        <message>
            <source>the contour's tick rate %1 was not taken: %2</source>
            <translation>der Takt %1 der Kontur wurde nicht übernommen: %2</translation>
        </message>
        <message>
            <source>the board did not come to rest after the contour's last tick</source>
            <translation>die Platine kam nach dem letzten Takt der Kontur nicht zum Stillstand</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::motion::SwitchExecutor</name>
        <message>
            <source>%1: no controller of this machine has coolant</source>
            <translation>%1: keine Steuerung dieser Maschine hat Kühlmittel</translation>
        </message>
        <message>
            <source>%1: no controller of this machine has a spindle</source>
            <translation>%1: keine Steuerung dieser Maschine hat eine Spindel</translation>
        </message>
        <message>
            <source>controller "%1": %2</source>
            <translation>Steuerung „%1“: %2</translation>
        </message>
        <message>
            <source>%1: the machine has no digital outputs</source>
            <translation>%1: die Maschine hat keine digitalen Ausgänge</translation>
        </message>
        <message>
            <source>%1: the machine's outputs are 1..%2</source>
            <translation>%1: die Ausgänge der Maschine sind 1..%2</translation>
        </message>
        <message>
            <source>S%1 is above the spindle's maxRpm %2 (the machine file's spindle scale)</source>
            <translation>S%1 liegt über maxRpm %2 der Spindel (Spindelskala der Maschinendatei)</translation>
        </message>
        <message>
            <source>controller "%1" cannot reverse its spindle: use M3</source>
            <translation>Steuerung "%1" kann die Drehrichtung ihrer Spindel nicht umkehren: M3 verwenden</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::motion::WaitExecutor</name>
        <message>
            <source>input %1 did not reach its level in time</source>
            <translation>Eingang %1 hat seinen Pegel nicht rechtzeitig erreicht</translation>
        </message>
        <message>
            <source>the machine has no input %1</source>
            <translation>die Maschine hat keinen Eingang %1</translation>
        </message>
        <message>
            <source>input %1: %2</source>
            <translation>Eingang %1: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::nanotec::Codec</name>
        <message>
            <source>'|0' is never sent: the drive would stop answering (manual 6.4)</source>
            <translation>'|0' wird nie gesendet: der Antrieb würde nicht mehr antworten (Handbuch 6.4)</translation>
        </message>
        <message>
            <source>'@A' is never sent: it starts the bootloader (manual 5.32)</source>
            <translation>'@A' wird nie gesendet: es startet den Bootloader (Handbuch 5.32)</translation>
        </message>
        <message>
            <source>positioning</source>
            <translation>Positionierung</translation>
        </message>
        <message>
            <source>speed</source>
            <translation>Drehzahl</translation>
        </message>
        <message>
            <source>flag positioning</source>
            <translation>Flag-Positionierung</translation>
        </message>
        <message>
            <source>clock-direction</source>
            <translation>Takt-Richtung</translation>
        </message>
        <message>
            <source>analog</source>
            <translation>analog</translation>
        </message>
        <message>
            <source>joystick</source>
            <translation>Joystick</translation>
        </message>
        <message>
            <source>unused</source>
            <translation>unbenutzt</translation>
        </message>
        <message>
            <source>ready</source>
            <translation>bereit</translation>
        </message>
        <message>
            <source>busy</source>
            <translation>beschäftigt</translation>
        </message>
        <message>
            <source>zero position reached</source>
            <translation>Nullposition erreicht</translation>
        </message>
        <message>
            <source>position error</source>
            <translation>Positionsfehler</translation>
        </message>
        <message>
            <source>input 1 still set while ready</source>
            <translation>Eingang 1 noch gesetzt, obwohl bereit</translation>
        </message>
        <message>
            <source>mode %1</source>
            <translation>Modus %1</translation>
        </message>
        <message>
            <source>no error</source>
            <translation>kein Fehler</translation>
        </message>
        <message>
            <source>undervoltage</source>
            <translation>Unterspannung</translation>
        </message>
        <message>
            <source>over-temperature</source>
            <translation>Übertemperatur</translation>
        </message>
        <message>
            <source>the driver chip reported an error</source>
            <translation>der Treiberbaustein hat einen Fehler gemeldet</translation>
        </message>
        <message>
            <source>nonsensical data in the EEPROM</source>
            <translation>unsinnige Daten im EEPROM</translation>
        </message>
        <message>
            <source>internal error</source>
            <translation>interner Fehler</translation>
        </message>
        <message>
            <source>unknown error code %1</source>
            <translation>unbekannter Fehlercode %1</translation>
        </message>
        <message>
            <source>read reply without a command</source>
            <translation>Leseantwort ohne Befehl</translation>
        </message>
        <message>
            <source>error memory reply without a slot number</source>
            <translation>Antwort des Fehlerspeichers ohne Platznummer</translation>
        </message>
        <message>
            <source>malformed error memory reply</source>
            <translation>fehlerhafte Antwort des Fehlerspeichers</translation>
        </message>
        <message>
            <source>read reply for record '%1' (records are 1..%2)</source>
            <translation>Leseantwort für Satz '%1' (Sätze sind 1..%2)</translation>
        </message>
        <message>
            <source>read reply without a numeric value</source>
            <translation>Leseantwort ohne Zahlenwert</translation>
        </message>
        <message>
            <source>'%1' is not a record setting (section 4)</source>
            <translation>'%1' ist keine Satzeinstellung (Abschnitt 4)</translation>
        </message>
        <message>
            <source>record setting '%1' given twice</source>
            <translation>Satzeinstellung '%1' zweimal angegeben</translation>
        </message>
        <message>
            <source>malformed record string</source>
            <translation>fehlerhafter Satz-String</translation>
        </message>
        <message>
            <source>long reply without a keyword</source>
            <translation>lange Antwort ohne Schlüsselwort</translation>
        </message>
        <message>
            <source>long reply without a numeric value</source>
            <translation>lange Antwort ohne Zahlenwert</translation>
        </message>
        <message>
            <source>non-ASCII bytes in reply</source>
            <translation>Nicht-ASCII-Bytes in der Antwort</translation>
        </message>
        <message>
            <source>address with more than three digits</source>
            <translation>Adresse mit mehr als drei Ziffern</translation>
        </message>
        <message>
            <source>reply from invalid address %1</source>
            <translation>Antwort von ungültiger Adresse %1</translation>
        </message>
        <message>
            <source>reply without a command</source>
            <translation>Antwort ohne Befehl</translation>
        </message>
        <message>
            <source>reply without an address</source>
            <translation>Antwort ohne Adresse</translation>
        </message>
        <message>
            <source>malformed firmware string</source>
            <translation>fehlerhafter Firmware-String</translation>
        </message>
        <message>
            <source>echo with a non-numeric value</source>
            <translation>Echo mit nicht numerischem Wert</translation>
        </message>
        <message>
            <source>reply longer than %1 bytes</source>
            <translation>Antwort länger als %1 Bytes</translation>
        </message>
        <message>
            <source>frame interrupted by a new '#'</source>
            <translation>Rahmen durch ein neues '#' unterbrochen</translation>
        </message>
        <message>
            <source>command longer than %1 bytes</source>
            <translation>Befehl länger als %1 Bytes</translation>
        </message>
        <message>
            <source>command without a valid address</source>
            <translation>Befehl ohne gültige Adresse</translation>
        </message>
        <message>
            <source>command without a body</source>
            <translation>Befehl ohne Inhalt</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::nanotec::NanotecBus</name>
        <message>
            <source>link is not open</source>
            <translation>Verbindung ist nicht geöffnet</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::nanotec::NanotecClosedLoop</name>
        <message>
            <source>%1 is already in its %2</source>
            <translation>%1 ist bereits in seiner %2</translation>
        </message>
        <message>
            <source>direction of the closed-loop reference run must be -1 or 1, not %1</source>
            <translation>die Richtung der Regelungs-Referenzfahrt muss -1 oder 1 sein, nicht %1</translation>
        </message>
        <message>
            <source>calibration run (!101)</source>
            <translation>Kalibrierfahrt (!101)</translation>
        </message>
        <message>
            <source>closed-loop reference run (!8)</source>
            <translation>Regelungs-Referenzfahrt (!8)</translation>
        </message>
        <message>
            <source>motor pole pairs %1: closed loop works with 50 or 100 only (8.6)</source>
            <translation>Polpaare des Motors %1: die Regelung arbeitet nur mit 50 oder 100 (8.6)</translation>
        </message>
        <message>
            <source>encoder increments %1: closed loop works with 1600 or 2000 only (8.7)</source>
            <translation>Encoderinkremente %1: die Regelung arbeitet nur mit 1600 oder 2000 (8.7)</translation>
        </message>
        <message>
            <source>encoder revolutions %1: closed loop works with 1 only (8.8)</source>
            <translation>Encoderumdrehungen %1: die Regelung arbeitet nur mit 1 (8.8)</translation>
        </message>
        <message>
            <source>closed loop not enabled on %1: %2; with wrong motor data the motor can speed up beyond its mechanical limits (manual 8.1)</source>
            <translation>Regelung an %1 nicht eingeschaltet: %2; mit falschen Motordaten kann der Motor über seine mechanische Belastbarkeit hinaus hochdrehen (Handbuch 8.1)</translation>
        </message>
        <message>
            <source>%1 ignored closed loop on: it needs the calibration run (!101) for this motor and the closed-loop reference run (!8) since it was switched on (manual 8.1)</source>
            <translation>%1 hat „Regelung ein“ ignoriert: er braucht die Kalibrierfahrt (!101) für diesen Motor und seit dem Einschalten die Regelungs-Referenzfahrt (!8) (Handbuch 8.1)</translation>
        </message>
        <message>
            <source>%1 kept closed loop on</source>
            <translation>%1 hat die Regelung eingeschaltet gelassen</translation>
        </message>
        <message>
            <source>closed loop is on; switch it off first</source>
            <translation>die Regelung ist eingeschaltet; zuerst ausschalten</translation>
        </message>
        <message>
            <source>%1 not started on %2: %3</source>
            <translation>%1 an %2 nicht gestartet: %3</translation>
        </message>
        <message>
            <source>%1 running, %2 s</source>
            <translation>%1 läuft, %2 s</translation>
        </message>
        <message>
            <source>%1 stopped answering during its %2; %3</source>
            <translation>%1 antwortet während seiner %2 nicht mehr; %3</translation>
        </message>
        <message>
            <source>%1 of %2 did not end within %3 s; stopped ('S')</source>
            <translation>%1 von %2 endete nicht innerhalb von %3 s; gestoppt ('S')</translation>
        </message>
        <message>
            <source>%1 was ready again at the first status read after 'A': that the %2 ran is not confirmed</source>
            <translation>%1 war bei der ersten Statusabfrage nach 'A' schon wieder bereit: dass die %2 gelaufen ist, ist nicht bestätigt</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>no entry in the error memory</source>
            <translation>kein Eintrag im Fehlerspeicher</translation>
        </message>
        <message>
            <source>is the encoder connected? The drive is not calibrated</source>
            <translation>ist der Encoder angeschlossen? Der Antrieb ist nicht kalibriert</translation>
        </message>
        <message>
            <source>is the encoder connected? The axis is not referenced and closed loop cannot be switched on</source>
            <translation>ist der Encoder angeschlossen? Die Achse ist nicht referenziert, und die Regelung kann nicht eingeschaltet werden</translation>
        </message>
        <message>
            <source>%1 of %2 failed: the drive reports a position error (%3); %4. Clear the error with reset-position-error (5.14) before the next run</source>
            <translation>%1 von %2 fehlgeschlagen: der Antrieb meldet einen Positionsfehler (%3); %4. Den Fehler vor der nächsten Fahrt mit reset-position-error (5.14) zurücksetzen</translation>
        </message>
        <message>
            <source>the drive is not calibrated; run it again</source>
            <translation>der Antrieb ist nicht kalibriert; die Fahrt wiederholen</translation>
        </message>
        <message>
            <source>the axis is not referenced</source>
            <translation>die Achse ist nicht referenziert</translation>
        </message>
        <message>
            <source>%1 of %2 ended, but its result was not read back (%3)</source>
            <translation>%1 von %2 ist beendet, ihr Ergebnis wurde aber nicht zurückgelesen (%3)</translation>
        </message>
        <message>
            <source>%1 of %2 aborted (%3): %4</source>
            <translation>%1 von %2 abgebrochen (%3): %4</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::nanotec::NanotecController</name>
        <message>
            <source>axis map: address %1 of axis %2 is invalid or used twice (allowed 1..254, one drive per axis)</source>
            <translation>Achszuordnung: Adresse %1 der Achse %2 ist ungültig oder doppelt vergeben (erlaubt 1..254, ein Antrieb pro Achse)</translation>
        </message>
        <message>
            <source>no drive answered %1 status sweeps in a row</source>
            <translation>kein Antrieb hat auf %1 Statusrunden in Folge geantwortet</translation>
        </message>
        <message>
            <source>drive %1 (axis %2)</source>
            <translation>Antrieb %1 (Achse %2)</translation>
        </message>
        <message>
            <source>no transport</source>
            <translation>keine Übertragungsstrecke</translation>
        </message>
        <message>
            <source>already connecting</source>
            <translation>Verbindung wird bereits aufgebaut</translation>
        </message>
        <message>
            <source>no drive answered at address %1 (19200 baud 8N1)</source>
            <translation>kein Antrieb hat unter Adresse %1 geantwortet (19200 Baud 8N1)</translation>
        </message>
        <message>
            <source>no answer from drive %1; the other drives work</source>
            <translation>keine Antwort von Antrieb %1; die anderen Antriebe arbeiten</translation>
        </message>
        <message>
            <source>%1 stopped answering (%2 status polls unanswered)</source>
            <translation>%1 antwortet nicht mehr (%2 Statusabfragen unbeantwortet)</translation>
        </message>
        <message>
            <source>not answering</source>
            <translation>antwortet nicht</translation>
        </message>
        <message>
            <source>no status yet</source>
            <translation>noch kein Status</translation>
        </message>
        <message>
            <source>this machine has no axis %1</source>
            <translation>diese Maschine hat keine Achse %1</translation>
        </message>
        <message>
            <source>emergency stop is active; reset it first</source>
            <translation>Not-Aus ist aktiv; zuerst zurücksetzen</translation>
        </message>
        <message>
            <source>%1 is not answering</source>
            <translation>%1 antwortet nicht</translation>
        </message>
        <message>
            <source>axis %1 runs in speed mode (jog or velocity move); stop it first</source>
            <translation>Achse %1 läuft im Drehzahlmodus (Tippbetrieb oder Geschwindigkeitsfahrt); zuerst stoppen</translation>
        </message>
        <message>
            <source>axis %1 is still moving (the drive is not ready)</source>
            <translation>Achse %1 ist noch in Bewegung (der Antrieb ist nicht bereit)</translation>
        </message>
        <message>
            <source>absolute move refused: position of axis %1 is unknown, reference it first</source>
            <translation>Absolutfahrt abgelehnt: Position der Achse %1 ist unbekannt, zuerst referenzieren</translation>
        </message>
        <message>
            <source>not connected</source>
            <translation>nicht verbunden</translation>
        </message>
        <message>
            <source>move of axis %1: %2 steps exceed the 32-bit range (6.7)</source>
            <translation>Fahrt der Achse %1: %2 Schritte überschreiten den 32-Bit-Bereich (6.7)</translation>
        </message>
        <message>
            <source>target of axis %1 exceeds the 32-bit range (6.7)</source>
            <translation>Ziel der Achse %1 überschreitet den 32-Bit-Bereich (6.7)</translation>
        </message>
        <message>
            <source>no axis to reference: every direction is 0</source>
            <translation>keine Achse zu referenzieren: jede Richtung ist 0</translation>
        </message>
        <message>
            <source>axis %1 was stopped at speed (ramp too long); its position is suspect until referenced</source>
            <translation>Achse %1 wurde in voller Fahrt gestoppt (Rampe zu lang); ihre Position ist bis zur Referenzfahrt zweifelhaft</translation>
        </message>
        <message>
            <source>axis %1 is in a velocity move; stop it first</source>
            <translation>Achse %1 ist in einer Geschwindigkeitsfahrt; zuerst stoppen</translation>
        </message>
        <message>
            <source>velocity of axis %1: %2 steps/s is outside 0..25000 (6.9)</source>
            <translation>Geschwindigkeit der Achse %1: %2 Schritte/s liegt außerhalb von 0..25000 (6.9)</translation>
        </message>
        <message>
            <source>stop</source>
            <translation>Stopp</translation>
        </message>
        <message>
            <source>emergency stop</source>
            <translation>Not-Aus</translation>
        </message>
        <message>
            <source>reply '%1' carries no value</source>
            <translation>Antwort '%1' enthält keinen Wert</translation>
        </message>
        <message>
            <source>%1 does not know the command '%2' (it answered '?')</source>
            <translation>%1 kennt den Befehl '%2' nicht (Antwort '?')</translation>
        </message>
        <message>
            <source>%1 did not answer '%2' in time</source>
            <translation>%1 hat auf '%2' nicht rechtzeitig geantwortet</translation>
        </message>
        <message>
            <source>%1: garbled reply to '%2' (%3)</source>
            <translation>%1: verstümmelte Antwort auf '%2' (%3)</translation>
        </message>
        <message>
            <source>'%1' to %2 was cancelled (stop, panic or disconnect)</source>
            <translation>'%1' an %2 wurde abgebrochen (Stopp, Panik-Stopp oder Trennen)</translation>
        </message>
        <message>
            <source>unknown axis '%1' (this machine has %2)</source>
            <translation>unbekannte Achse '%1' (diese Maschine hat %2)</translation>
        </message>
        <message>
            <source>no drive answered the status request</source>
            <translation>kein Antrieb hat auf die Statusabfrage geantwortet</translation>
        </message>
        <message>
            <source>not a Nanotec frame: expected '#&lt;address&gt;&lt;command&gt;\r'</source>
            <translation>kein Nanotec-Rahmen: erwartet '#&lt;Adresse&gt;&lt;Befehl&gt;\r'</translation>
        </message>
        <message>
            <source>no reply to '%1' from address %2</source>
            <translation>keine Antwort auf '%1' von Adresse %2</translation>
        </message>
        <message>
            <source>cancelled</source>
            <translation>abgebrochen</translation>
        </message>
        <message>
            <source>scan cancelled</source>
            <translation>Suche abgebrochen</translation>
        </message>
        <message>
            <source>scan range must lie within 1..254</source>
            <translation>der Suchbereich muss innerhalb von 1..254 liegen</translation>
        </message>
        <message>
            <source>record must be 0..32</source>
            <translation>der Satz muss 0..32 sein</translation>
        </message>
        <message>
            <source>unknown Nanotec operation '%1'</source>
            <translation>unbekannte Nanotec-Operation '%1'</translation>
        </message>
        <message>
            <source>malformed error memory reply '%1'</source>
            <translation>fehlerhafte Antwort des Fehlerspeichers '%1'</translation>
        </message>
        <message>
            <source>%1 echoed '%2' to '%3'</source>
            <translation>%1 hat '%2' auf '%3' zurückgegeben</translation>
        </message>
        <message>
            <source>%1 on %2: wrote %3, but the drive kept %4 (drives echo invalid values and silently ignore them)</source>
            <translation>%1 an %2: %3 geschrieben, aber der Antrieb behielt %4 (Antriebe geben ungültige Werte zurück und ignorieren sie stillschweigend)</translation>
        </message>
        <message>
            <source>unknown parameter '%1'</source>
            <translation>unbekannter Parameter '%1'</translation>
        </message>
        <message>
            <source>%1 sent no record string: '%2'</source>
            <translation>%1 hat keinen Satz-String gesendet: '%2'</translation>
        </message>
        <message>
            <source>record must be 0 (RAM) or 1..32, not %1</source>
            <translation>der Satz muss 0 (RAM) oder 1..32 sein, nicht %1</translation>
        </message>
        <message>
            <source>record must be 1..32, not %1</source>
            <translation>der Satz muss 1..32 sein, nicht %1</translation>
        </message>
        <message>
            <source>'%1' is not a record setting (section 4)</source>
            <translation>'%1' ist keine Satzeinstellung (Abschnitt 4)</translation>
        </message>
        <message>
            <source>record %1 of %2: %3 is %4 in the EEPROM, not %5</source>
            <translation>Satz %1 von %2: %3 ist im EEPROM %4, nicht %5</translation>
        </message>
        <message>
            <source>%1 of record %2 on %3 did not take effect (the drive ignores invalid record numbers)</source>
            <translation>%1 von Satz %2 an %3 wurde nicht wirksam (der Antrieb ignoriert ungültige Satznummern)</translation>
        </message>
        <message>
            <source>saving</source>
            <translation>Speichern</translation>
        </message>
        <message>
            <source>loading</source>
            <translation>Laden</translation>
        </message>
        <message>
            <source>%1 reads %2=%3 instead of %4 (the drive ignored the setting); not started</source>
            <translation>%1 liest %2=%3 statt %4 (die Steuerung hat die Einstellung ignoriert); nicht gestartet</translation>
        </message>
        <message>
            <source>%1 sent; not confirmed by %2: %3</source>
            <translation>%1 gesendet; nicht bestätigt von %2: %3</translation>
        </message>
        <message>
            <source>axis %1: %2 steps/s is below the drive's start frequency u=%3 steps/s; refused</source>
            <translation>Achse %1: %2 Schritte/s liegt unter der Startfrequenz u=%3 Schritte/s der Steuerung; abgelehnt</translation>
        </message>
        <message>
            <source>jog on axis %1: %2</source>
            <translation>Joggen auf Achse %1: %2</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1 (%2)</translation>
        </message>
        <message>
            <source>%1; already written: %2</source>
            <translation>%1; bereits geschrieben: %2</translation>
        </message>
        <message>
            <source>%1 %2 is already used by another drive on the bus; no communication would be possible (manual 5.4)</source>
            <translation>%1 %2 wird bereits von einem anderen Antrieb am Bus benutzt; eine Kommunikation wäre nicht möglich (Handbuch 5.4)</translation>
        </message>
        <message>
            <source>%1 reports %2 %3, not %4</source>
            <translation>%1 meldet %2 %3, nicht %4</translation>
        </message>
        <message>
            <source>%1 did not take %2 %3: nothing answers there</source>
            <translation>%1 hat %2 %3 nicht übernommen: dort antwortet nichts</translation>
        </message>
        <message>
            <source>%1 %2 is already used by %3</source>
            <translation>%1 %2 wird bereits von %3 benutzt</translation>
        </message>
        <message>
            <source>%1; sent but not read back: %2</source>
            <translation>%1; gesendet, aber nicht zurückgelesen: %2</translation>
        </message>
        <message>
            <source>stopped</source>
            <translation>gestoppt</translation>
        </message>
        <message>
            <source>%1 reports a position error; reset the position error first</source>
            <translation>%1 meldet einen Positionsfehler; zuerst den Positionsfehler zurücksetzen</translation>
        </message>
        <message>
            <source>%1 reports a position error; reset it first with %2</source>
            <translation>%1 meldet einen Positionsfehler; zuerst mit %2 zurücksetzen</translation>
        </message>
        <message>
            <source>%1 reports a position error (encoder deviation above %2); reset the position error to go on</source>
            <translation>%1 meldet einen Positionsfehler (Encoderabweichung über %2); zum Weiterarbeiten den Positionsfehler zurücksetzen</translation>
        </message>
        <message>
            <source>%1 reports a position error (encoder deviation above %2); reset it with %3</source>
            <translation>%1 meldet einen Positionsfehler (Encoderabweichung über %2); mit %3 zurücksetzen</translation>
        </message>
        <message>
            <source>%1 answers again after a silence: it may have been switched off and on; its position is unknown, reference axis %2</source>
            <translation>%1 antwortet nach einer Funkstille wieder: er könnte aus- und wieder eingeschaltet worden sein; seine Position ist unbekannt, Achse %2 referenzieren</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::nanotec::NanotecSimulator</name>
        <message>
            <source>--no-encoder: no drive at address %1 (see --drives)</source>
            <translation>--no-encoder: kein Antrieb mit Adresse %1 (siehe --drives)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::nanotec::Presentation</name>
        <message>
            <source>The drive is ready.</source>
            <translation>Der Antrieb ist bereit.</translation>
        </message>
        <message>
            <source>Zero position reached.</source>
            <translation>Nullposition erreicht.</translation>
        </message>
        <message>
            <source>Position error: the encoder disagrees with the demand position.</source>
            <translation>Positionsfehler: der Geber weicht von der Sollposition ab.</translation>
        </message>
        <message>
            <source>Input 1 is still set while the drive is ready again.</source>
            <translation>Eingang 1 ist noch gesetzt, obwohl der Antrieb wieder bereit ist.</translation>
        </message>
        <message>
            <source>Mode, bit 0.</source>
            <translation>Modus, Bit 0.</translation>
        </message>
        <message>
            <source>Mode, bit 1.</source>
            <translation>Modus, Bit 1.</translation>
        </message>
        <message>
            <source>Mode, bit 2.</source>
            <translation>Modus, Bit 2.</translation>
        </message>
        <message>
            <source>Send a command, e.g. #1$ (status of drive 1) or #2Zo (top speed of drive 2); the final CR is added (1.1).</source>
            <translation>Befehl senden, z. B. #1$ (Status von Antrieb 1) oder #2Zo (Maximalfrequenz von Antrieb 2); das abschließende CR wird angehängt (1.1).</translation>
        </message>
        <message>
            <source>Drive status ($, 5.21)</source>
            <translation>Antriebsstatus ($, 5.21)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program</name>
        <message>
            <source>%1 is not closed</source>
            <translation>%1 ist nicht geschlossen</translation>
        </message>
        <message>
            <source>%1 closes nothing that is open</source>
            <translation>%1 schließt nichts, was offen ist</translation>
        </message>
        <message>
            <source>%1 does not close %2 (line %3)</source>
            <translation>%1 schließt nicht %2 (Zeile %3)</translation>
        </message>
        <message>
            <source>%1 inside %2 sub (line %3): subroutines do not nest</source>
            <translation>%1 innerhalb von %2 sub (Zeile %3): Unterprogramme lassen sich nicht verschachteln</translation>
        </message>
        <message>
            <source>%1 is defined twice (line %2 first)</source>
            <translation>%1 ist zweimal definiert (zuerst in Zeile %2)</translation>
        </message>
        <message>
            <source>%1 is outside %2 sub</source>
            <translation>%1 steht außerhalb von %2 sub</translation>
        </message>
        <message>
            <source>%1 is outside a loop %2</source>
            <translation>%1 steht außerhalb einer Schleife %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ArcPath</name>
        <message>
            <source>%1: the position of %2 is unknown, so the arc has no start: reference the axis first (G28 %2)</source>
            <translation>%1: Die Position von %2 ist unbekannt, der Bogen hat also keinen Anfang: zuerst die Achse referenzieren (G28 %2)</translation>
        </message>
        <message>
            <source>%1: the machine has no axis %2, which an arc in this plane turns</source>
            <translation>%1: Die Maschine hat keine Achse %2, die ein Bogen in dieser Ebene dreht</translation>
        </message>
        <message>
            <source>%1: %2 and %3 have different units (%4, %5); an arc needs one</source>
            <translation>%1: %2 und %3 haben verschiedene Einheiten (%4, %5); ein Bogen braucht eine</translation>
        </message>
        <message>
            <source>%1 with R: the end point is the start point; a full circle takes I, J or K</source>
            <translation>%1 mit R: Der Endpunkt ist der Startpunkt; ein Vollkreis nimmt I, J oder K</translation>
        </message>
        <message>
            <source>%1: R%2 is too short to reach the end point, %3 away</source>
            <translation>%1: R%2 ist zu kurz, um den Endpunkt zu erreichen, der %3 entfernt ist</translation>
        </message>
        <message>
            <source>%1: the arc's radius is larger than %2</source>
            <translation>%1: Der Radius des Bogens ist größer als %2</translation>
        </message>
        <message>
            <source>%1: the centre lies on the start or the end point</source>
            <translation>%1: Der Mittelpunkt liegt auf dem Start- oder Endpunkt</translation>
        </message>
        <message>
            <source>%1: the end point is not on the arc: radius %2 at the start, %3 at the end, %4 apart (at most %5 allowed): check the centre and the end point</source>
            <translation>%1: Der Endpunkt liegt nicht auf dem Bogen: Radius %2 am Anfang, %3 am Ende, %4 Unterschied (höchstens %5 erlaubt): Mittelpunkt und Endpunkt prüfen</translation>
        </message>
        <message>
            <source>%1: the arc needs more than %2 chords</source>
            <translation>%1: Der Bogen braucht mehr als %2 Sehnen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ContourMoves</name>
        <message>
            <source>F%1 is too fast for the contour stream of controller "%2": at its %3 ticks/s (one step per tick at most) this move's highest feed is F%4</source>
            <translation>F%1 ist zu schnell für den Konturstrom der Steuerung "%2": bei ihren %3 Takten/s (höchstens ein Schritt je Takt) ist der höchste Vorschub dieser Bewegung F%4</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::CutterCompensation</name>
        <message>
            <source>cutter compensation needs the axes X and Y in millimetres</source>
            <translation>die Werkzeugradiuskorrektur braucht die Achsen X und Y in Millimetern</translation>
        </message>
        <message>
            <source>cutter compensation begins where X or Y is unknown: reference them first (G28)</source>
            <translation>die Werkzeugradiuskorrektur beginnt, wo X oder Y unbekannt ist: zuerst referenzieren (G28)</translation>
        </message>
        <message>
            <source>cutter compensation: tool %1 is not in the tool table; give its diameter with G41.1/G42.1 D&lt;diameter&gt;</source>
            <translation>Werkzeugradiuskorrektur: Werkzeug %1 steht nicht in der Werkzeugtabelle; seinen Durchmesser mit G41.1/G42.1 D&lt;Durchmesser&gt; angeben</translation>
        </message>
        <message>
            <source>cutter compensation: the tool (diameter %1) cannot reach the inside corner of lines %2 and %3 without cutting into the part</source>
            <translation>Werkzeugradiuskorrektur: das Werkzeug (Durchmesser %1) erreicht die Innenecke der Zeilen %2 und %3 nicht, ohne ins Werkstück zu schneiden</translation>
        </message>
        <message>
            <source>%1 enters cutter compensation: the first move after G41/G42 must be a straight line (G0 or G1)</source>
            <translation>%1 beginnt die Werkzeugradiuskorrektur: die erste Bewegung nach G41/G42 muss eine Gerade sein (G0 oder G1)</translation>
        </message>
        <message>
            <source>cutter compensation: the entry move (%1) is not longer than the tool's radius (%2), as LinuxCNC requires</source>
            <translation>Werkzeugradiuskorrektur: die Anfahrbewegung (%1) ist nicht länger als der Werkzeugradius (%2), wie LinuxCNC es verlangt</translation>
        </message>
        <message>
            <source>cutter compensation: the tool's radius (%1) is not less than the arc's (%2): the tool does not fit inside it, as LinuxCNC refuses</source>
            <translation>Werkzeugradiuskorrektur: der Werkzeugradius (%1) ist nicht kleiner als der des Bogens (%2): das Werkzeug passt nicht hinein, wie LinuxCNC es ablehnt</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::DrillCycle</name>
        <message>
            <source>%1: the position of %2 is unknown, so the cycle has no start: reference the axis first (G28 %2)</source>
            <translation>%1: Die Position von %2 ist unbekannt, der Zyklus hat also keinen Anfang: zuerst die Achse referenzieren (G28 %2)</translation>
        </message>
        <message>
            <source>%1: the machine has no axis Z, which a drilling cycle drills along</source>
            <translation>%1: Die Maschine hat keine Achse Z, entlang der ein Bohrzyklus bohrt</translation>
        </message>
        <message>
            <source>%1 takes more than %2 moves: make Q larger or L smaller</source>
            <translation>%1 braucht mehr als %2 Bewegungen: Q größer oder L kleiner wählen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::MachineWorkOffsets</name>
        <message>
            <source>Zero %1 refused: its position is unknown; reference it first.</source>
            <translation>%1 nullen abgelehnt: die Position ist unbekannt; zuerst referenzieren.</translation>
        </message>
        <message>
            <source>Zero %1 refused: the axis is moving.</source>
            <translation>%1 nullen abgelehnt: die Achse fährt.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::MdiSession</name>
        <message>
            <source>an MDI line is one line</source>
            <translation>eine MDI-Zeile ist eine Zeile</translation>
        </message>
        <message>
            <source>the line has nothing to run</source>
            <translation>die Zeile enthält nichts auszuführen</translation>
        </message>
        <message>
            <source>cutter compensation (G41, G42) runs in programs, not in MDI</source>
            <translation>die Werkzeugradiuskorrektur (G41, G42) läuft in Programmen, nicht in MDI</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::NgcExpression</name>
        <message>
            <source>the expression nests deeper than %1</source>
            <translation>der Ausdruck ist tiefer als %1 verschachtelt</translation>
        </message>
        <message>
            <source>a value is missing at the end of the line</source>
            <translation>am Ende der Zeile fehlt ein Wert</translation>
        </message>
        <message>
            <source>"%1" does not start a value</source>
            <translation>mit „%1“ beginnt kein Wert</translation>
        </message>
        <message>
            <source>%1 is not a finite number</source>
            <translation>%1 ist keine endliche Zahl</translation>
        </message>
        <message>
            <source>"[" is not closed by "]"</source>
            <translation>„[“ wird nicht durch „]“ geschlossen</translation>
        </message>
        <message>
            <source>an operator or "]" is missing before "%1"</source>
            <translation>vor „%1“ fehlt ein Operator oder „]“</translation>
        </message>
        <message>
            <source>division by zero</source>
            <translation>Division durch null</translation>
        </message>
        <message>
            <source>MOD by zero</source>
            <translation>MOD durch null</translation>
        </message>
        <message>
            <source>a negative number to a fractional power</source>
            <translation>eine negative Zahl hoch einen gebrochenen Exponenten</translation>
        </message>
        <message>
            <source>the result is not a finite number</source>
            <translation>das Ergebnis ist keine endliche Zahl</translation>
        </message>
        <message>
            <source>"%1" is not a value: a number, #, [ or a function</source>
            <translation>„%1“ ist kein Wert: eine Zahl, #, [ oder eine Funktion</translation>
        </message>
        <message>
            <source>EXISTS takes a named parameter: EXISTS[#&lt;name&gt;]</source>
            <translation>EXISTS nimmt einen benannten Parameter: EXISTS[#&lt;name&gt;]</translation>
        </message>
        <message>
            <source>%1[%2]: %3</source>
            <translation>%1[%2]: %3</translation>
        </message>
        <message>
            <source>ATAN takes two values: ATAN[y]/[x]</source>
            <translation>ATAN nimmt zwei Werte: ATAN[y]/[x]</translation>
        </message>
        <message>
            <source>outside -1..1</source>
            <translation>außerhalb von -1..1</translation>
        </message>
        <message>
            <source>needs a value above 0</source>
            <translation>braucht einen Wert über 0</translation>
        </message>
        <message>
            <source>needs a value of 0 or more</source>
            <translation>braucht einen Wert von 0 oder mehr</translation>
        </message>
        <message>
            <source>unknown function "%1"</source>
            <translation>unbekannte Funktion „%1“</translation>
        </message>
        <message>
            <source>%1: the result is not a finite number</source>
            <translation>%1: das Ergebnis ist keine endliche Zahl</translation>
        </message>
        <message>
            <source>a parameter name is written #&lt;name&gt;</source>
            <translation>ein Parametername wird #&lt;name&gt; geschrieben</translation>
        </message>
        <message>
            <source>the parameter name is not closed by "&gt;"</source>
            <translation>der Parametername wird nicht durch „&gt;“ geschlossen</translation>
        </message>
        <message>
            <source>the parameter name is empty</source>
            <translation>der Parametername ist leer</translation>
        </message>
        <message>
            <source>#%1 is not a parameter: parameters are whole numbers from 1</source>
            <translation>#%1 ist kein Parameter: Parameter sind ganze Zahlen ab 1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::NgcInterpreter</name>
        <message>
            <source>%1:%2:%3: %4</source>
            <translation>%1:%2:%3: %4</translation>
        </message>
        <message>
            <source>internal: no reason</source>
            <translation>intern: kein Grund</translation>
        </message>
        <message>
            <source>the subroutine's file ends before its endsub</source>
            <translation>die Datei des Unterprogramms endet vor seinem endsub</translation>
        </message>
        <message>
            <source>the program gives out more than %1 lines to run: a runaway loop? (the check stops there)</source>
            <translation>das Programm gibt mehr als %1 auszuführende Zeilen aus: eine Endlosschleife? (die Prüfung bricht dort ab)</translation>
        </message>
        <message>
            <source>the worked-out program cannot be kept (see the log)</source>
            <translation>das ausgewertete Programm kann nicht zwischengespeichert werden (siehe Protokoll)</translation>
        </message>
        <message>
            <source>#&lt;%1&gt; is LinuxCNC's, read-only</source>
            <translation>#&lt;%1&gt; gehört LinuxCNC und ist nur lesbar</translation>
        </message>
        <message>
            <source>%1 needs a value: [ … ]</source>
            <translation>%1 braucht einen Wert: [ … ]</translation>
        </message>
        <message>
            <source>%1 takes one value; "%2" follows it</source>
            <translation>%1 nimmt einen Wert; danach folgt „%2“</translation>
        </message>
        <message>
            <source>%1 (line %2) has run %3 passes: a runaway loop? (the check stops a loop there)</source>
            <translation>%1 (Zeile %2) hat %3 Durchläufe ausgeführt: eine Endlosschleife? (die Prüfung bricht eine Schleife dort ab)</translation>
        </message>
        <message>
            <source>%1 needs a whole count from 0 to %2, got %3</source>
            <translation>%1 braucht eine ganze Anzahl von 0 bis %2, erhalten: %3</translation>
        </message>
        <message>
            <source>internal: %1 is not a loop statement</source>
            <translation>intern: %1 ist keine Schleifenanweisung</translation>
        </message>
        <message>
            <source>a call takes at most %1 arguments (#1..#%1)</source>
            <translation>ein Aufruf nimmt höchstens %1 Argumente (#1..#%1)</translation>
        </message>
        <message>
            <source>%1: calls nest deeper than %2 (LinuxCNC's limit)</source>
            <translation>%1: Aufrufe sind tiefer als %2 verschachtelt (Grenze von LinuxCNC)</translation>
        </message>
        <message>
            <source>%1: the program has no %2 sub</source>
            <translation>%1: das Programm enthält kein %2 sub</translation>
        </message>
        <message>
            <source>%1: neither the program nor %2 has %3 sub</source>
            <translation>%1: weder das Programm noch %2 enthält %3 sub</translation>
        </message>
        <message>
            <source>%1 outside a call</source>
            <translation>%1 außerhalb eines Aufrufs</translation>
        </message>
        <message>
            <source>%1 is larger than %2 bytes</source>
            <translation>%1 ist größer als %2 Bytes</translation>
        </message>
        <message>
            <source>cannot read %1: %2</source>
            <translation>%1 kann nicht gelesen werden: %2</translation>
        </message>
        <message>
            <source>%1 does not define O&lt;%2&gt; sub</source>
            <translation>%1 definiert kein O&lt;%2&gt; sub</translation>
        </message>
        <message>
            <source>the program runs more than %1 lines (a long line counts once per 64 characters): a runaway loop? (the check stops there)</source>
            <translation>das Programm führt mehr als %1 Zeilen aus (eine lange Zeile zählt je 64 Zeichen einmal): eine Endlosschleife? (die Prüfung bricht dort ab)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::NgcLineExpander</name>
        <message>
            <source>the comment is not closed: ")" is missing</source>
            <translation>der Kommentar ist nicht geschlossen: „)“ fehlt</translation>
        </message>
        <message>
            <source>"=" is missing: a parameter is set with #…=value</source>
            <translation>„=“ fehlt: ein Parameter wird mit #…=Wert gesetzt</translation>
        </message>
        <message>
            <source>unexpected character "%1"</source>
            <translation>unerwartetes Zeichen „%1“</translation>
        </message>
        <message>
            <source>%1%2 is beyond the values StepDeck takes (±%3)</source>
            <translation>%1%2 liegt außerhalb der Werte, die StepDeck annimmt (±%3)</translation>
        </message>
        <message>
            <source>an O word stands first on its line (after an N number at most)</source>
            <translation>ein O-Wort steht als erstes in seiner Zeile (höchstens nach einer N-Nummer)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::NgcParameters</name>
        <message>
            <source>#%1 holds a probing result (G38), which StepDeck does not run</source>
            <translation>#%1 enthält ein Antastergebnis (G38); StepDeck führt G38 nicht aus</translation>
        </message>
        <message>
            <source>#%1 is LinuxCNC's stored G28/G30 position; StepDeck's G28 is the reference run and keeps none</source>
            <translation>#%1 ist die in LinuxCNC gespeicherte G28/G30-Position; G28 ist in StepDeck die Referenzfahrt und speichert keine</translation>
        </message>
        <message>
            <source>#%1 is G92's offset, which line %2 set from where the axes stand: only the run knows it</source>
            <translation>#%1 ist der G92-Nullpunkt, den Zeile %2 aus der Position der Achsen gesetzt hat: nur der Lauf kennt ihn</translation>
        </message>
        <message>
            <source>#%1: StepDeck has the coordinate systems G54..G59 (#5221..#5330)</source>
            <translation>#%1: StepDeck hat die Koordinatensysteme G54..G59 (#5221..#5330)</translation>
        </message>
        <message>
            <source>#%1 is an offset that line %2 changed (G10): only the run knows it</source>
            <translation>#%1 ist ein Nullpunkt, den Zeile %2 geändert hat (G10): nur der Lauf kennt ihn</translation>
        </message>
        <message>
            <source>#%1 is the loaded tool's, known only at run time</source>
            <translation>#%1 gehört zum eingesetzten Werkzeug und ist erst zur Laufzeit bekannt</translation>
        </message>
        <message>
            <source>#%1 is the current position, known only at run time</source>
            <translation>#%1 ist die aktuelle Position und erst zur Laufzeit bekannt</translation>
        </message>
        <message>
            <source>#%1 is not a parameter: numbered parameters are #1..#%2</source>
            <translation>#%1 ist kein Parameter: nummerierte Parameter sind #1..#%2</translation>
        </message>
        <message>
            <source>#&lt;%1&gt; is not set (LinuxCNC's predefined values of the machine's state are known only at run time, and StepDeck works a program out before it runs)</source>
            <translation>#&lt;%1&gt; ist nicht gesetzt (die vordefinierten Werte von LinuxCNC zum Zustand der Maschine sind erst zur Laufzeit bekannt, und StepDeck wertet ein Programm aus, bevor es läuft)</translation>
        </message>
        <message>
            <source>#&lt;%1&gt; is not set here (a name without "_" is local to its subroutine)</source>
            <translation>#&lt;%1&gt; ist hier nicht gesetzt (ein Name ohne „_“ ist lokal in seinem Unterprogramm)</translation>
        </message>
        <message>
            <source>#%1 is a coordinate system's offset, read-only here: set it with G10 L2 or at the position display</source>
            <translation>#%1 ist der Nullpunkt eines Koordinatensystems, hier nur lesbar: mit G10 L2 oder in der Positionsanzeige setzen</translation>
        </message>
        <message>
            <source>#%1 is reserved by LinuxCNC and read-only</source>
            <translation>#%1 ist von LinuxCNC reserviert und nur lesbar</translation>
        </message>
        <message>
            <source>#5399 holds what M66 read, and no M66 has run before this line</source>
            <translation>#5399 enthält, was M66 gelesen hat, und vor dieser Zeile ist kein M66 gelaufen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramCheck</name>
        <message>
            <source>run from line %1: the program has no blocks</source>
            <translation>Start ab Zeile %1: das Programm hat keine Sätze</translation>
        </message>
        <message>
            <source>run from line %1: the program's last block is on line %2</source>
            <translation>Start ab Zeile %1: der letzte Satz des Programms steht in Zeile %2</translation>
        </message>
        <message>
            <source>run from line %1 is inside the repeat of line %2: start at line %2 or after its endrepeat</source>
            <translation>Start ab Zeile %1 liegt in der Wiederholung von Zeile %2: ab Zeile %2 oder nach ihrem endrepeat starten</translation>
        </message>
        <message>
            <source>%1: G0 in a program with G1 on controller "%2": its fast speed (%3) cannot be read back to be put back after G1; move %1 with G1 and F only, or with G0 only</source>
            <translation>%1: G0 in einem Programm mit G1 auf Steuerung „%2“: ihre Eilganggeschwindigkeit (%3) kann nicht zurückgelesen werden, um sie nach G1 wiederherzustellen; %1 nur mit G1 und F oder nur mit G0 bewegen</translation>
        </message>
        <message>
            <source>more errors follow; only the first %1 are listed</source>
            <translation>weitere Fehler folgen; nur die ersten %1 sind aufgeführt</translation>
        </message>
        <message>
            <source>the axes of a block start together, each at its own rate; the block ends when every axis has arrived</source>
            <translation>die Achsen eines Satzes starten gemeinsam, jede mit ihrer eigenen Geschwindigkeit; der Satz endet, wenn jede Achse angekommen ist</translation>
        </message>
        <message>
            <source>the machine has no axis %1</source>
            <translation>die Maschine hat keine Achse %1</translation>
        </message>
        <message>
            <source>%1: controller "%2" takes no feed rate, so G1 cannot move it; use G0</source>
            <translation>%1: Steuerung "%2" nimmt keinen Vorschub, G1 kann sie nicht bewegen; G0 verwenden</translation>
        </message>
        <message>
            <source>%1: controller "%2" has no parameter %3 for the feed rate</source>
            <translation>%1: Steuerung "%2" hat keinen Parameter %3 für den Vorschub</translation>
        </message>
        <message>
            <source>F%1 is %2 steps/s on %3; controller "%4" takes %5..%6 steps/s (%7)</source>
            <translation>F%1 ergibt %2 Schritte/s auf %3; Steuerung "%4" nimmt %5..%6 Schritte/s (%7)</translation>
        </message>
        <message>
            <source>%1: the machine has no digital inputs</source>
            <translation>%1: die Maschine hat keine digitalen Eingänge</translation>
        </message>
        <message>
            <source>%1: the machine's inputs are 1..%2</source>
            <translation>%1: die Eingänge der Maschine sind 1..%2</translation>
        </message>
        <message>
            <source>%1: the position is unknown, so an absolute move could go anywhere: reference the axis first (G28 %1) or move it relatively (G91)</source>
            <translation>%1: die Position ist unbekannt, eine absolute Fahrt könnte überall hinführen: die Achse zuerst referenzieren (G28 %1) oder relativ fahren (G91)</translation>
        </message>
        <message>
            <source>%1 reaches %2 %3, outside the soft limits %4..%5 %3</source>
            <translation>%1 erreicht %2 %3, außerhalb der Software-Endlagen %4..%5 %3</translation>
        </message>
        <message>
            <source>F%1: controller "%2" would refuse its rate: %3</source>
            <translation>F%1: Steuerung „%2“ würde ihre Geschwindigkeit ablehnen: %3</translation>
        </message>
        <message>
            <source>%1; F%2 or less is taken, or change the setup on the Setup page</source>
            <translation>%1; F%2 oder weniger wird angenommen, oder das Setup auf der Seite Setup ändern</translation>
        </message>
        <message>
            <source>%1; set it on the Setup page first</source>
            <translation>%1; zuerst auf der Seite Setup setzen</translation>
        </message>
        <message>
            <source>%1: controller "%2": %3</source>
            <translation>%1: Steuerung „%2“: %3</translation>
        </message>
        <message>
            <source>%1 reaches %2 %3 in work coordinates, %4 %3 in machine coordinates: outside the soft limits %5..%6 %3 (machine)</source>
            <translation>%1 erreicht %2 %3 in Werkstückkoordinaten, %4 %3 in Maschinenkoordinaten: außerhalb der Software-Endlagen %5..%6 %3 (Maschine)</translation>
        </message>
        <message>
            <source>T%1: tool %1 is not in the machine's tool table</source>
            <translation>T%1: Werkzeug %1 steht nicht in der Werkzeugtabelle der Maschine</translation>
        </message>
        <message>
            <source>G43: the machine's tool table is empty: enter tool %1's length first</source>
            <translation>G43: Die Werkzeugtabelle der Maschine ist leer: zuerst die Länge von Werkzeug %1 eintragen</translation>
        </message>
        <message>
            <source>G43: tool %1 is not in the machine's tool table</source>
            <translation>G43: Werkzeug %1 steht nicht in der Werkzeugtabelle der Maschine</translation>
        </message>
        <message>
            <source>G43: the machine has no axis %1 for tool %2's length</source>
            <translation>G43: Die Maschine hat keine Achse %1 für die Länge von Werkzeug %2</translation>
        </message>
        <message>
            <source>%1: %4 moves it at the fast speed in a program with G1 on controller "%2", whose fast speed (%3) cannot be read back to be put back after G1; drill with G1 and F only</source>
            <translation>%1: %4 fährt sie im Eilgang, in einem Programm mit G1 auf Steuerung "%2", deren Eilganggeschwindigkeit (%3) sich nicht zurücklesen lässt, um sie nach G1 wiederherzustellen; nur mit G1 und F bohren</translation>
        </message>
        <message>
            <source>the run's arcs and cycles need more than %1 moves</source>
            <translation>die Bögen und Zyklen des Laufs brauchen mehr als %1 Bewegungen</translation>
        </message>
        <message>
            <source>G93 F%1 (the move in %2 s) moves %3 at %4 steps/s; controller "%5" takes %6..%7 steps/s (%8)</source>
            <translation>G93 F%1 (die Bewegung in %2 s) fährt %3 mit %4 Schritten/s; Controller "%5" nimmt %6..%7 Schritte/s (%8)</translation>
        </message>
        <message>
            <source>the repeats run more than %1 blocks beyond the program's own</source>
            <translation>die Wiederholungen führen mehr als %1 Sätze über die des Programms hinaus aus</translation>
        </message>
        <message>
            <source>the move runs in the contour stream of controller "%1", but %2</source>
            <translation>die Bewegung läuft im Konturstrom der Steuerung "%1", aber %2</translation>
        </message>
        <message>
            <source>this feed move drives axes of controllers %1 together; the machine file forbids that ("crossControllerFeed": false), since their path between the ends is only approximate</source>
            <translation>diese Vorschubbewegung fährt Achsen der Steuerungen %1 gemeinsam; die Maschinendatei verbietet das ("crossControllerFeed": false), da ihre Bahn zwischen den Endpunkten nur ungefähr ist</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>each axis of a feed move runs at its share of F, so the path is followed at F</source>
            <translation>jede Achse einer Vorschubbewegung fährt mit ihrem Anteil an F, so wird die Bahn mit F abgefahren</translation>
        </message>
        <message>
            <source>contours (G64) run on the path at F as one step stream; a block of its own (G61) moves each axis at its own rate, starting together</source>
            <translation>Konturen (G64) laufen als ein Schrittstrom mit F auf der Bahn; ein einzelner Satz (G61) bewegt jede Achse mit ihrer eigenen Geschwindigkeit, gemeinsam startend</translation>
        </message>
        <message>
            <source>feed moves across controllers (%1 in all, the first on line %2) follow their path only approximately: up to about %3 %4 off</source>
            <translation>Vorschubbewegungen über mehrere Steuerungen (%1 insgesamt, die erste in Zeile %2) folgen ihrer Bahn nur ungefähr: bis etwa %3 %4 daneben</translation>
        </message>
        <message>
            <source>run from line %1: a program with parameters or O words runs its lines in the order its control flow gives; run it from its start</source>
            <translation>Start ab Zeile %1: ein Programm mit Parametern oder O-Worten führt seine Zeilen in der Reihenfolge seines Programmablaufs aus; von Anfang an starten</translation>
        </message>
        <message>
            <source>the offsets changed since the program's parameters were worked out: check it again</source>
            <translation>die Nullpunkte haben sich geändert, seit die Parameter des Programms ausgewertet wurden: erneut prüfen</translation>
        </message>
        <message>
            <source>the run holds inside a repeat, whose passes a check from here cannot count: the new offsets cannot be checked for the rest</source>
            <translation>der Lauf hält innerhalb einer Wiederholung, deren Durchläufe eine Prüfung ab hier nicht zählen kann: die neuen Nullpunkte lassen sich für den Rest nicht prüfen</translation>
        </message>
        <message>
            <source>tool lengths by touch-off (the machine file's toolLength): G43 adds no length; set the work Z for the tool in the spindle before the run</source>
            <translation>Werkzeuglängen durch Antasten (toolLength der Maschinendatei): G43 addiert keine Länge; den Werkstück-Nullpunkt von Z vor dem Lauf für das Werkzeug in der Spindel setzen</translation>
        </message>
        <message numerus="yes">
            <source>tool lengths by touch-off (the machine file's toolLength): the run holds at %n tool change(s) (M6, line(s) %1) until the work Z is set for the new tool; G43 adds no length</source>
            <translation>
                <numerusform>Werkzeuglängen durch Antasten (toolLength der Maschinendatei): der Lauf hält an %n Werkzeugwechsel (M6, Zeile %1), bis der Werkstück-Nullpunkt von Z für das neue Werkzeug gesetzt ist; G43 addiert keine Länge</numerusform>
                <numerusform>Werkzeuglängen durch Antasten (toolLength der Maschinendatei): der Lauf hält an %n Werkzeugwechseln (M6, Zeilen %1), bis der Werkstück-Nullpunkt von Z für das neue Werkzeug gesetzt ist; G43 addiert keine Länge</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%1 (also on %n more line(s))</source>
            <translation>
                <numerusform>%1 (auch in %n weiteren Zeile)</numerusform>
                <numerusform>%1 (auch in %n weiteren Zeilen)</numerusform>
            </translation>
        </message>
        <message>
            <source>below its %1: feed mode has no ramp</source>
            <translation>unter ihrer %1: der Vorschubmodus hat keine Rampe</translation>
        </message>
        <message>
            <source>%1 at most</source>
            <translation>höchstens %1</translation>
        </message>
        <message>
            <source>above the %1 steps/s controller "%2" takes (%3)</source>
            <translation>über den %1 Schritten/s, die Steuerung "%2" annimmt (%3)</translation>
        </message>
        <message>
            <source>G93 F%1 (the move in %2 s) moves %3 at %4 steps/s, %5: the move takes %6 s</source>
            <translation>G93 F%1 (die Bewegung in %2 s) bewegt %3 mit %4 Schritten/s, %5: die Bewegung dauert %6 s</translation>
        </message>
        <message>
            <source>F%1 moves %2 at %3 steps/s, %4: the move runs at F%5</source>
            <translation>F%1 bewegt %2 mit %3 Schritten/s, %4: die Bewegung läuft mit F%5</translation>
        </message>
        <message>
            <source>F%1 is %2 steps/s on %3, %4: %3 runs at F%5</source>
            <translation>F%1 sind %2 Schritte/s auf %3, %4: %3 läuft mit F%5</translation>
        </message>
        <message>
            <source>S%1 runs at S%2, the spindle's maxRpm (the machine file's spindle scale)</source>
            <translation>S%1 läuft mit S%2, der maxRpm der Spindel (Spindelskala der Maschinendatei)</translation>
        </message>
        <message>
            <source>run from line %1: the move to its start point first (%2): %3</source>
            <translation>Start ab Zeile %1: zuerst die Fahrt zu ihrem Startpunkt (%2): %3</translation>
        </message>
        <message>
            <source>run from line %1: %2 first, as the lines before it left it: %3</source>
            <translation>Start ab Zeile %1: zuerst %2, wie die Zeilen davor es hinterließen: %3</translation>
        </message>
        <message>
            <source>F%1 runs at F%2, the highest this move can run at in the contour stream of controller "%3" (%4 ticks/s, one step per tick at most)</source>
            <translation>F%1 läuft mit F%2, dem Höchsten, mit dem diese Bewegung im Konturstrom von Steuerung "%3" laufen kann (%4 Takte/s, höchstens ein Schritt je Takt)</translation>
        </message>
        <message>
            <source>M4 runs as M3 on this laser: the beam's power is S, constant (GRBL's M4 lowers the power where the feed slows; StepDeck's controllers have no such power)</source>
            <translation>M4 läuft auf diesem Laser als M3: die Leistung des Strahls ist S, gleichbleibend (GRBLs M4 senkt die Leistung, wo der Vorschub langsamer wird; StepDecks Steuerungen haben keine solche Leistung)</translation>
        </message>
        <message>
            <source>S%1 runs at S%2, the laser's full power (the machine file's spindle scale)</source>
            <translation>S%1 läuft mit S%2, der vollen Leistung des Lasers (Spindelskala der Maschinendatei)</translation>
        </message>
        <message>
            <source>run from line %1: cutter compensation (G41/G42) is on there; start on a line before it is turned on, or after its G40</source>
            <translation>Start ab Zeile %1: dort ist die Werkzeugradiuskorrektur (G41/G42) an; auf einer Zeile vor ihrem Einschalten oder nach ihrem G40 beginnen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramCoordinates</name>
        <message>
            <source>G10 L20: the position of %1 is unknown: reference it first (G28 %1)</source>
            <translation>G10 L20: Die Position von %1 ist unbekannt: zuerst referenzieren (G28 %1)</translation>
        </message>
        <message>
            <source>G92: the position of %1 is unknown: reference it first (G28 %1)</source>
            <translation>G92: Die Position von %1 ist unbekannt: zuerst referenzieren (G28 %1)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramExpansion</name>
        <message>
            <source>a program with parameters or O words is read into memory whole: at most %1 MB, this one has %2 MB</source>
            <translation>ein Programm mit Parametern oder O-Worten wird ganz in den Speicher gelesen: höchstens %1 MB, dieses hat %2 MB</translation>
        </message>
        <message>
            <source>the worked-out program cannot be kept: %1</source>
            <translation>das ausgewertete Programm kann nicht zwischengespeichert werden: %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramLexer</name>
        <message>
            <source>the comment is not closed: ")" is missing</source>
            <translation>der Kommentar ist nicht geschlossen: „)“ fehlt</translation>
        </message>
        <message>
            <source>%1 needs a number</source>
            <translation>%1 braucht eine Zahl</translation>
        </message>
        <message>
            <source>%1: "%2%3" is not a decimal number</source>
            <translation>%1: „%2%3“ ist keine Dezimalzahl</translation>
        </message>
        <message>
            <source>%1: %2 is not a finite number</source>
            <translation>%1: %2 ist keine endliche Zahl</translation>
        </message>
        <message>
            <source>unexpected character "%1"</source>
            <translation>unerwartetes Zeichen „%1“</translation>
        </message>
        <message>
            <source>"]" is missing</source>
            <translation>„]“ fehlt</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramLine</name>
        <message>
            <source>%1 appears twice on the line</source>
            <translation>%1 steht zweimal in der Zeile</translation>
        </message>
        <message>
            <source>the machine has no axis %1 (it has %2)</source>
            <translation>die Maschine hat keine Achse %1 (sie hat %2)</translation>
        </message>
        <message>
            <source>axis %1 appears twice on the line</source>
            <translation>Achse %1 steht zweimal in der Zeile</translation>
        </message>
        <message>
            <source>N (a line number) stands only at the start of a line</source>
            <translation>N (eine Satznummer) steht nur am Zeilenanfang</translation>
        </message>
        <message>
            <source>O%1 stands alone on its line</source>
            <translation>O%1 steht allein in seiner Zeile</translation>
        </message>
        <message>
            <source>%1 is not a word of StepDeck programs</source>
            <translation>%1 ist kein Wort von StepDeck-Programmen</translation>
        </message>
        <message>
            <source>%1 is not supported</source>
            <translation>%1 wird nicht unterstützt</translation>
        </message>
        <message>
            <source>G90 and G91 on one line</source>
            <translation>G90 und G91 in einer Zeile</translation>
        </message>
        <message>
            <source>G20 and G21 on one line</source>
            <translation>G20 und G21 in einer Zeile</translation>
        </message>
        <message>
            <source>%1: N takes a whole number</source>
            <translation>%1: N nimmt eine ganze Zahl</translation>
        </message>
        <message>
            <source>%1: the feed rate must be greater than 0</source>
            <translation>%1: der Vorschub muss größer als 0 sein</translation>
        </message>
        <message>
            <source>%1 is not used by %2</source>
            <translation>%1 wird von %2 nicht verwendet</translation>
        </message>
        <message>
            <source>%1 is not used on a line without an action</source>
            <translation>%1 wird in einer Zeile ohne Aktion nicht verwendet</translation>
        </message>
        <message>
            <source>%1 needs %2</source>
            <translation>%1 braucht %2</translation>
        </message>
        <message>
            <source>%1 must be greater than %2 and at most %3</source>
            <translation>%1 muss größer als %2 und höchstens %3 sein</translation>
        </message>
        <message>
            <source>%1 must lie within %2..%3</source>
            <translation>%1 muss zwischen %2 und %3 liegen</translation>
        </message>
        <message>
            <source>%1: the number must be a whole number 0..9999</source>
            <translation>%1: die Nummer muss eine ganze Zahl 0..9999 sein</translation>
        </message>
        <message>
            <source>%1: L3 waits for high, L4 for low</source>
            <translation>%1: L3 wartet auf High, L4 auf Low</translation>
        </message>
        <message>
            <source>%1: O takes a whole number</source>
            <translation>%1: O nimmt eine ganze Zahl</translation>
        </message>
        <message>
            <source>only "O%1 repeat [count]" and "O%1 endrepeat" are supported</source>
            <translation>nur „O%1 repeat [Anzahl]“ und „O%1 endrepeat“ werden unterstützt</translation>
        </message>
        <message>
            <source>repeat needs a count: O%1 repeat [3]</source>
            <translation>repeat braucht eine Anzahl: O%1 repeat [3]</translation>
        </message>
        <message>
            <source>the repeat count must be a whole number 0..1000000</source>
            <translation>die Anzahl der Wiederholungen muss eine ganze Zahl 0..1000000 sein</translation>
        </message>
        <message>
            <source>G95 (feed per revolution) is not supported: no controller reports its spindle's revolutions; use G94</source>
            <translation>G95 (Vorschub pro Umdrehung) wird nicht unterstützt: keine Steuerung meldet die Umdrehungen ihrer Spindel; G94 verwenden</translation>
        </message>
        <message>
            <source>%1 and %2 on one line: they are of one modal group</source>
            <translation>%1 und %2 in einer Zeile: sie gehören zu einer modalen Gruppe</translation>
        </message>
        <message>
            <source>%1: G64 P is a tolerance, not below 0</source>
            <translation>%1: G64 P ist eine Toleranz, nicht unter 0</translation>
        </message>
        <message>
            <source>%1: G64 Q is a tolerance, not below 0</source>
            <translation>%1: G64 Q ist eine Toleranz, nicht unter 0</translation>
        </message>
        <message>
            <source>T appears twice on the line</source>
            <translation>T steht zweimal in der Zeile</translation>
        </message>
        <message>
            <source>%1: T takes a tool number, whole, 0..%2</source>
            <translation>%1: T nimmt eine Werkzeugnummer, ganzzahlig, 0..%2</translation>
        </message>
        <message>
            <source>M6 needs a tool: T on this line or an earlier one</source>
            <translation>M6 braucht ein Werkzeug: T in dieser oder einer früheren Zeile</translation>
        </message>
        <message>
            <source>Load tool %1</source>
            <translation>Werkzeug %1 einsetzen</translation>
        </message>
        <message>
            <source>Load tool %1 (%2)</source>
            <translation>Werkzeug %1 einsetzen (%2)</translation>
        </message>
        <message>
            <source>axis words need G0, G1, G2 or G3 before them</source>
            <translation>Achsworte brauchen davor G0, G1, G2 oder G3</translation>
        </message>
        <message>
            <source>%1 needs a feed rate: F on this line or an earlier one</source>
            <translation>%1 braucht einen Vorschub: F in dieser oder einer früheren Zeile</translation>
        </message>
        <message>
            <source>%1: %2 in the %3 plane (%4) moves %5, %6 and %7 only</source>
            <translation>%1: %2 in der %3-Ebene (%4) bewegt nur %5, %6 und %7</translation>
        </message>
        <message>
            <source>%1 is not used by %2 in the %3 plane (%4): its centre takes %5 and %6</source>
            <translation>%1 wird von %2 in der %3-Ebene (%4) nicht verwendet: sein Mittelpunkt nimmt %5 und %6</translation>
        </message>
        <message>
            <source>%1: an arc takes its centre by I, J, K or by R, not both</source>
            <translation>%1: Ein Bogen nimmt seinen Mittelpunkt über I, J, K oder über R, nicht beides</translation>
        </message>
        <message>
            <source>%1 needs its centre: %2 and %3, or R</source>
            <translation>%1 braucht seinen Mittelpunkt: %2 und %3 oder R</translation>
        </message>
        <message>
            <source>%1: the radius must not be 0</source>
            <translation>%1: Der Radius darf nicht 0 sein</translation>
        </message>
        <message>
            <source>%1 with R needs an end point in the plane (%2 or %3); a full circle takes %4 and %5</source>
            <translation>%1 mit R braucht einen Endpunkt in der Ebene (%2 oder %3); ein Vollkreis nimmt %4 und %5</translation>
        </message>
        <message>
            <source>%1: P counts the arc's turns, a whole number 1..%2</source>
            <translation>%1: P zählt die Umläufe des Bogens, eine ganze Zahl 1..%2</translation>
        </message>
        <message>
            <source>G53 appears twice on the line</source>
            <translation>G53 steht zweimal in der Zeile</translation>
        </message>
        <message>
            <source>G53 moves in machine coordinates with G0 or G1 only</source>
            <translation>G53 fährt nur mit G0 oder G1 in Maschinenkoordinaten</translation>
        </message>
        <message>
            <source>G53 takes absolute machine coordinates: not in G91</source>
            <translation>G53 nimmt absolute Maschinenkoordinaten: nicht in G91</translation>
        </message>
        <message>
            <source>G92 needs axis words: the values the axes' present positions get</source>
            <translation>G92 braucht Achsworte: die Werte, die die jetzigen Positionen der Achsen erhalten</translation>
        </message>
        <message>
            <source>%1: G10 R (a rotated coordinate system) is not supported</source>
            <translation>%1: G10 R (ein gedrehtes Koordinatensystem) wird nicht unterstützt</translation>
        </message>
        <message>
            <source>G10 %1 is not supported: L2 and L20 set the coordinate systems</source>
            <translation>G10 %1 wird nicht unterstützt: L2 und L20 setzen die Koordinatensysteme</translation>
        </message>
        <message>
            <source>%1: G10 sets P1 (G54) to P6 (G59), P0 the system in effect</source>
            <translation>%1: G10 setzt P1 (G54) bis P6 (G59), P0 das geltende System</translation>
        </message>
        <message>
            <source>%1 is used only with G43</source>
            <translation>%1 wird nur mit G43 verwendet</translation>
        </message>
        <message>
            <source>%1: H takes a tool number, whole, 0..%2</source>
            <translation>%1: H nimmt eine Werkzeugnummer, ganzzahlig, 0..%2</translation>
        </message>
        <message>
            <source>G43 needs H&lt;n&gt; or a tool loaded by M6 (T&lt;n&gt; M6) before it</source>
            <translation>G43 braucht H&lt;n&gt; oder ein zuvor mit M6 eingesetztes Werkzeug (T&lt;n&gt; M6)</translation>
        </message>
        <message>
            <source>%1 must lie within 0..1000000</source>
            <translation>%1 muss im Bereich 0..1000000 liegen</translation>
        </message>
        <message>
            <source>the hole's bottom</source>
            <translation>den Grund der Bohrung</translation>
        </message>
        <message>
            <source>the retract plane</source>
            <translation>die Rückzugsebene</translation>
        </message>
        <message>
            <source>the depth of each peck</source>
            <translation>die Tiefe jeder Zustellung</translation>
        </message>
        <message>
            <source>the dwell at the bottom in seconds</source>
            <translation>die Verweilzeit am Grund in Sekunden</translation>
        </message>
        <message>
            <source>%1 needs %2: %3</source>
            <translation>%1 braucht %2: %3</translation>
        </message>
        <message>
            <source>%1: Q, the depth of each peck, must be greater than 0</source>
            <translation>%1: Q, die Tiefe jeder Zustellung, muss größer als 0 sein</translation>
        </message>
        <message>
            <source>%1: P must lie within 0..1000000 seconds</source>
            <translation>%1: P muss im Bereich 0..1000000 Sekunden liegen</translation>
        </message>
        <message>
            <source>%1: drilling cycles run in the XY plane (G17) only</source>
            <translation>%1: Bohrzyklen laufen nur in der XY-Ebene (G17)</translation>
        </message>
        <message>
            <source>%1: a drilling cycle moves X, Y and Z only, not %2</source>
            <translation>%1: Ein Bohrzyklus bewegt nur X, Y und Z, nicht %2</translation>
        </message>
        <message>
            <source>%1: L, the repeats, takes a whole number 1..%2</source>
            <translation>%1: L, die Wiederholungen, nimmt eine ganze Zahl 1..%2</translation>
        </message>
        <message>
            <source>%1: in G91, Z is measured down from R: not above 0</source>
            <translation>%1: In G91 wird Z von R aus nach unten gemessen: nicht über 0</translation>
        </message>
        <message>
            <source>%1: Z%2 lies above R%3: the hole's bottom must lie below the retract plane</source>
            <translation>%1: Z%2 liegt über R%3: Der Grund der Bohrung muss unter der Rückzugsebene liegen</translation>
        </message>
        <message>
            <source>%1 in inverse time (G93) needs F on its line: the move takes 1/F minutes</source>
            <translation>%1 in inverser Zeit (G93) braucht F in seiner Zeile: die Bewegung dauert 1/F Minuten</translation>
        </message>
        <message>
            <source>a drilling cycle cannot run in inverse time (G93), as in LinuxCNC: switch to G94 and give F before the cycle</source>
            <translation>ein Bohrzyklus kann nicht in inverser Zeit (G93) laufen, wie in LinuxCNC: vor dem Zyklus auf G94 schalten und F angeben</translation>
        </message>
        <message>
            <source>%1 (a Fanuc-style subprogram) is not supported: write the subprogram as O&lt;name&gt; sub … endsub and call it with O&lt;name&gt; call</source>
            <translation>%1 (ein Unterprogramm im Fanuc-Stil) wird nicht unterstützt: das Unterprogramm als O&lt;name&gt; sub … endsub schreiben und mit O&lt;name&gt; call aufrufen</translation>
        </message>
        <message>
            <source>%1: more than %2 M words on one line (LinuxCNC runs at most %2)</source>
            <translation>%1: mehr als %2 M-Wörter in einer Zeile (LinuxCNC führt höchstens %2 aus)</translation>
        </message>
        <message>
            <source>%1 and %2 both take axis words: write them on two lines</source>
            <translation>%1 und %2 nehmen beide Achsworte: in zwei Zeilen schreiben</translation>
        </message>
        <message>
            <source>%1 and %2 both take P: write them on two lines</source>
            <translation>%1 und %2 nehmen beide P: in zwei Zeilen schreiben</translation>
        </message>
        <message>
            <source>polar coordinates (@, ^) need the axes X and Y (the machine has %1)</source>
            <translation>Polarkoordinaten (@, ^) brauchen die Achsen X und Y (die Maschine hat %1)</translation>
        </message>
        <message>
            <source>%1 is not used by %2: polar coordinates give a move's end</source>
            <translation>%1 wird von %2 nicht verwendet: Polarkoordinaten geben das Ende einer Bewegung an</translation>
        </message>
        <message>
            <source>polar coordinates (@, ^) work in the XY plane (G17) only, as in LinuxCNC</source>
            <translation>Polarkoordinaten (@, ^) gelten nur in der XY-Ebene (G17), wie in LinuxCNC</translation>
        </message>
        <message>
            <source>%1 beside polar coordinates (@, ^): give one or the other, as in LinuxCNC</source>
            <translation>%1 neben Polarkoordinaten (@, ^): eines von beiden angeben, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>polar coordinates (@, ^) are not machine coordinates: not with G53, as in LinuxCNC</source>
            <translation>Polarkoordinaten (@, ^) sind keine Maschinenkoordinaten: nicht mit G53, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>polar coordinates in G91 add to where the tool stands: not supported; write @ and ^ in G90</source>
            <translation>Polarkoordinaten in G91 addieren sich zur Stelle, an der das Werkzeug steht: nicht unterstützt; @ und ^ in G90 schreiben</translation>
        </message>
        <message>
            <source>%1 alone takes the other from where the tool stands: not supported; give both @ (the distance) and ^ (the angle)</source>
            <translation>%1 allein nimmt das andere von der Stelle, an der das Werkzeug steht: nicht unterstützt; beide angeben, @ (den Abstand) und ^ (den Winkel)</translation>
        </message>
        <message>
            <source>%1 (a spline or NURBS curve) is not supported: let the CAM post write lines and arcs (G1, G2, G3)</source>
            <translation>%1 (eine Spline- oder NURBS-Kurve) wird nicht unterstützt: den CAM-Postprozessor Geraden und Bögen schreiben lassen (G1, G2, G3)</translation>
        </message>
        <message>
            <source>%1 (a lathe's diameter or radius mode) is not supported: StepDeck drives mills, routers, lasers and plotters</source>
            <translation>%1 (Durchmesser- oder Radiusmodus einer Drehmaschine) wird nicht unterstützt: StepDeck steuert Fräsen, Portalfräsen, Laser und Plotter</translation>
        </message>
        <message>
            <source>%1 (a circular pocket of some controllers) is not supported: let the CAM post write the pocket's arcs (G2, G3)</source>
            <translation>%1 (eine Kreistasche mancher Steuerungen) wird nicht unterstützt: den CAM-Postprozessor die Bögen der Tasche schreiben lassen (G2, G3)</translation>
        </message>
        <message>
            <source>%1 (Fanuc's polar coordinates) is not supported: write LinuxCNC's @ (the distance) and ^ (the angle)</source>
            <translation>%1 (Fanucs Polarkoordinaten) wird nicht unterstützt: LinuxCNCs @ (den Abstand) und ^ (den Winkel) schreiben</translation>
        </message>
        <message>
            <source>%1 (a stored position) is not supported: StepDeck's G28 references the axes; go to a machine position with G53 G0</source>
            <translation>%1 (eine gespeicherte Position) wird nicht unterstützt: StepDecks G28 referenziert die Achsen; eine Maschinenposition mit G53 G0 anfahren</translation>
        </message>
        <message>
            <source>%1 (threading with the spindle) is not supported: no controller of StepDeck's reads its spindle's revolutions</source>
            <translation>%1 (Gewindeschneiden mit der Spindel) wird nicht unterstützt: keine Steuerung von StepDeck liest die Umdrehungen ihrer Spindel</translation>
        </message>
        <message>
            <source>%1 (a probing move) is not supported: no controller of StepDeck's has a probe input; touch off by hand (the DRO's Zero) or with G10 L20</source>
            <translation>%1 (eine Antastbewegung) wird nicht unterstützt: keine Steuerung von StepDeck hat einen Tastereingang; von Hand antasten (Null in der Positionsanzeige) oder mit G10 L20</translation>
        </message>
        <message>
            <source>%1 (a tool length written in the program) is not supported: G43 H takes the tool table's length, or touch off Z (the machine file's "toolLength": "touchOff")</source>
            <translation>%1 (eine im Programm geschriebene Werkzeuglänge) wird nicht unterstützt: G43 H nimmt die Länge aus der Werkzeugtabelle, oder Z antasten ("toolLength": "touchOff" der Maschinendatei)</translation>
        </message>
        <message>
            <source>%1 (a local offset) is not supported: use G92 or a coordinate system (G10 L2, G54 to G59)</source>
            <translation>%1 (eine lokale Verschiebung) wird nicht unterstützt: G92 oder ein Koordinatensystem verwenden (G10 L2, G54 bis G59)</translation>
        </message>
        <message>
            <source>%1 (a rotated coordinate system) is not supported: let the CAM post rotate the path</source>
            <translation>%1 (ein gedrehtes Koordinatensystem) wird nicht unterstützt: den CAM-Postprozessor die Bahn drehen lassen</translation>
        </message>
        <message>
            <source>%1 (a lathe cycle in LinuxCNC, inch or millimetre mode in old Fanuc programs) is not supported: write G20 (inch) or G21 (mm) for the units</source>
            <translation>%1 (ein Drehzyklus in LinuxCNC, Zoll- oder Millimetermodus in alten Fanuc-Programmen) wird nicht unterstützt: für die Einheiten G20 (Zoll) oder G21 (mm) schreiben</translation>
        </message>
        <message>
            <source>%1 (a tapping cycle) is not supported: no controller of StepDeck's turns its spindle with the feed; G81, G82, G83 and G73 are</source>
            <translation>%1 (ein Gewindebohrzyklus) wird nicht unterstützt: keine Steuerung von StepDeck dreht ihre Spindel mit dem Vorschub; G81, G82, G83 und G73 werden unterstützt</translation>
        </message>
        <message>
            <source>%1 (a boring cycle) is not supported: write the holes with G81, or G82 for a dwell at the bottom</source>
            <translation>%1 (ein Ausdrehzyklus) wird nicht unterstützt: die Bohrungen mit G81 schreiben, oder mit G82 für eine Verweilzeit am Grund</translation>
        </message>
        <message>
            <source>%1 (constant surface speed, a lathe's) is not supported: S is the spindle's rpm (G97)</source>
            <translation>%1 (konstante Schnittgeschwindigkeit, die einer Drehmaschine) wird nicht unterstützt: S ist die Drehzahl der Spindel (G97)</translation>
        </message>
        <message>
            <source>%1 is a 3D printer's word (temperatures, fans, the extruder): not one of machine control; leave it out, or slice for a printer</source>
            <translation>%1 ist ein Wort eines 3D-Druckers (Temperaturen, Lüfter, Extruder): keines der Maschinensteuerung; weglassen oder für einen Drucker slicen</translation>
        </message>
        <message>
            <source>%1 (orienting the spindle) is not supported: no controller of StepDeck's can</source>
            <translation>%1 (die Spindel ausrichten) wird nicht unterstützt: keine Steuerung von StepDeck kann das</translation>
        </message>
        <message>
            <source>%1 (switching the overrides) is not supported: the feed override is always the operator's</source>
            <translation>%1 (die Overrides schalten) wird nicht unterstützt: der Vorschub-Override liegt immer beim Bediener</translation>
        </message>
        <message>
            <source>%1 (a pallet change) is not supported: write M0 to hold for the operator</source>
            <translation>%1 (ein Palettenwechsel) wird nicht unterstützt: M0 schreiben, um für den Bediener anzuhalten</translation>
        </message>
        <message>
            <source>%1 (the loaded tool set without a change) is not supported: write T&lt;n&gt; M6</source>
            <translation>%1 (das geladene Werkzeug ohne Wechsel setzen) wird nicht unterstützt: T&lt;n&gt; M6 schreiben</translation>
        </message>
        <message>
            <source>%1 (an output switched with the next move) is not supported: M64 and M65 switch it at once</source>
            <translation>%1 (ein mit der nächsten Bewegung geschalteter Ausgang) wird nicht unterstützt: M64 und M65 schalten ihn sofort</translation>
        </message>
        <message>
            <source>%1 (an analog output) is not supported: StepDeck's controllers have digital outputs (M64, M65)</source>
            <translation>%1 (ein Analogausgang) wird nicht unterstützt: StepDecks Steuerungen haben digitale Ausgänge (M64, M65)</translation>
        </message>
        <message>
            <source>%1 (saving or restoring the modal state) is not supported: set the modes again where they change</source>
            <translation>%1 (den modalen Zustand sichern oder wiederherstellen) wird nicht unterstützt: die Modi dort neu setzen, wo sie sich ändern</translation>
        </message>
        <message>
            <source>%1 (a user-defined M code, a program of a LinuxCNC configuration) is not supported</source>
            <translation>%1 (ein benutzerdefinierter M-Code, ein Programm einer LinuxCNC-Konfiguration) wird nicht unterstützt</translation>
        </message>
        <message>
            <source>O%1 with cutter compensation on: G40 before it (a repeat's passes would enter the path anew)</source>
            <translation>O%1 bei eingeschalteter Werkzeugradiuskorrektur: G40 davor (jeder Durchlauf der Wiederholung würde die Bahn neu anfahren)</translation>
        </message>
        <message>
            <source>turn cutter compensation off (G40) before it</source>
            <translation>die Werkzeugradiuskorrektur davor ausschalten (G40)</translation>
        </message>
        <message>
            <source>G28 with cutter compensation on: %1, as in LinuxCNC</source>
            <translation>G28 bei eingeschalteter Werkzeugradiuskorrektur: %1, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>M6 with cutter compensation on: %1, as in LinuxCNC</source>
            <translation>M6 bei eingeschalteter Werkzeugradiuskorrektur: %1, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>a drilling cycle with cutter compensation on: %1</source>
            <translation>ein Bohrzyklus bei eingeschalteter Werkzeugradiuskorrektur: %1</translation>
        </message>
        <message>
            <source>%1 changes the offsets under cutter compensation: %2, as in LinuxCNC</source>
            <translation>%1 ändert die Verschiebungen unter Werkzeugradiuskorrektur: %2, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>G53 with cutter compensation on: %1, as in LinuxCNC</source>
            <translation>G53 bei eingeschalteter Werkzeugradiuskorrektur: %1, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>inverse time (G93) with cutter compensation is not supported: use G94</source>
            <translation>inverse Zeit (G93) mit Werkzeugradiuskorrektur wird nicht unterstützt: G94 verwenden</translation>
        </message>
        <message>
            <source>%1: cutter compensation is on already: G40 first, as in LinuxCNC</source>
            <translation>%1: die Werkzeugradiuskorrektur ist schon an: zuerst G40, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>%1: cutter compensation works in the XY plane (G17) only</source>
            <translation>%1: die Werkzeugradiuskorrektur arbeitet nur in der XY-Ebene (G17)</translation>
        </message>
        <message>
            <source>%1 needs D: the tool's diameter</source>
            <translation>%1 braucht D: den Durchmesser des Werkzeugs</translation>
        </message>
        <message>
            <source>%1: the diameter must lie within 0..1000000</source>
            <translation>%1: der Durchmesser muss im Bereich 0..1000000 liegen</translation>
        </message>
        <message>
            <source>%1: D takes a tool number, whole, 0..%2 (G41.1 D takes a diameter)</source>
            <translation>%1: D nimmt eine ganze Werkzeugnummer 0..%2 (G41.1 D nimmt einen Durchmesser)</translation>
        </message>
        <message>
            <source>%1 needs D&lt;tool&gt; or a tool loaded by M6 (T&lt;n&gt; M6) before it</source>
            <translation>%1 braucht D&lt;Werkzeug&gt; oder ein zuvor mit M6 eingesetztes Werkzeug (T&lt;n&gt; M6)</translation>
        </message>
        <message>
            <source>the plane cannot change under cutter compensation: G40 first, as in LinuxCNC</source>
            <translation>die Ebene kann unter Werkzeugradiuskorrektur nicht wechseln: zuerst G40, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>the units cannot change under cutter compensation: G40 first, as in LinuxCNC</source>
            <translation>die Einheiten können unter Werkzeugradiuskorrektur nicht wechseln: zuerst G40, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>the coordinate system cannot change under cutter compensation: G40 first, as in LinuxCNC</source>
            <translation>das Koordinatensystem kann unter Werkzeugradiuskorrektur nicht wechseln: zuerst G40, wie in LinuxCNC</translation>
        </message>
        <message>
            <source>%1 leaves cutter compensation: the first move after G40 must be a straight line (G0 or G1), as in LinuxCNC</source>
            <translation>%1 beendet die Werkzeugradiuskorrektur: die erste Bewegung nach G40 muss eine Gerade sein (G0 oder G1), wie in LinuxCNC</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramParser</name>
        <message>
            <source>the program is longer than %1 lines</source>
            <translation>das Programm ist länger als %1 Zeilen</translation>
        </message>
        <message>
            <source>the line is longer than %1 characters</source>
            <translation>die Zeile ist länger als %1 Zeichen</translation>
        </message>
        <message>
            <source>repeats nest deeper than %1</source>
            <translation>Wiederholungen sind tiefer als %1 verschachtelt</translation>
        </message>
        <message>
            <source>O%1 endrepeat without its O%1 repeat</source>
            <translation>O%1 endrepeat ohne sein O%1 repeat</translation>
        </message>
        <message>
            <source>O%1 endrepeat does not close O%2 repeat (line %3)</source>
            <translation>O%1 endrepeat schließt nicht O%2 repeat (Zeile %3)</translation>
        </message>
        <message>
            <source>O%1 repeat is not closed by O%1 endrepeat</source>
            <translation>O%1 repeat wird nicht durch O%1 endrepeat geschlossen</translation>
        </message>
        <message>
            <source>more errors follow; only the first %1 are listed</source>
            <translation>weitere Fehler folgen; nur die ersten %1 sind aufgeführt</translation>
        </message>
        <message>
            <source>"%" stands only on the program's first line and, closing it, its last</source>
            <translation>„%“ steht nur in der ersten Zeile des Programms und, es schließend, in seiner letzten</translation>
        </message>
        <message>
            <source>the program opened with "%" (line %1) ends with neither "%" nor M2/M30</source>
            <translation>das mit „%“ (Zeile %1) eröffnete Programm endet weder mit „%“ noch mit M2/M30</translation>
        </message>
        <message>
            <source>%1 is a GRBL command (a setting, the alarm lock, a report or a jog): not run</source>
            <translation>%1 ist ein GRBL-Befehl (eine Einstellung, die Alarmsperre, ein Bericht oder ein Tippbetrieb): wird nicht ausgeführt</translation>
        </message>
        <message>
            <source>$H cannot run here</source>
            <translation>$H kann hier nicht laufen</translation>
        </message>
        <message numerus="yes">
            <source>%n line(s) after the program's end are not read, as in LinuxCNC (nothing after M2, M30 or the closing "%" runs)</source>
            <translation>
                <numerusform>%n Zeile nach dem Programmende wird nicht gelesen, wie in LinuxCNC (nichts nach M2, M30 oder dem schließenden "%" läuft)</numerusform>
                <numerusform>%n Zeilen nach dem Programmende werden nicht gelesen, wie in LinuxCNC (nichts nach M2, M30 oder dem schließenden "%" läuft)</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>block delete is on: %n line(s) starting with "/" are skipped, this one the first (switch it off to run them)</source>
            <translation>
                <numerusform>Satz ausblenden ist ein: %n Zeile, die mit "/" beginnt, wird übersprungen, diese (ausschalten, um sie auszuführen)</numerusform>
                <numerusform>Satz ausblenden ist ein: %n Zeilen, die mit "/" beginnen, werden übersprungen, diese als erste (ausschalten, um sie auszuführen)</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%1 on %n arc(s), this one the first: an offset along the plane's normal that is 0 is left out, as GRBL does (LinuxCNC refuses it; any other value is refused)</source>
            <translation>
                <numerusform>%1 an %n Bogen, diesem: ein Versatz entlang der Normalen der Ebene, der 0 ist, wird weggelassen, wie GRBL es tut (LinuxCNC weist ihn ab; jeder andere Wert wird abgewiesen)</numerusform>
                <numerusform>%1 an %n Bögen, diesem als erstem: ein Versatz entlang der Normalen der Ebene, der 0 ist, wird weggelassen, wie GRBL es tut (LinuxCNC weist ihn ab; jeder andere Wert wird abgewiesen)</numerusform>
            </translation>
        </message>
        <message>
            <source>more GRBL commands follow; only the first %1 are named</source>
            <translation>weitere GRBL-Befehle folgen; nur die ersten %1 sind genannt</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramReader</name>
        <message>
            <source>the program was not read</source>
            <translation>das Programm wurde nicht gelesen</translation>
        </message>
        <message>
            <source>the program's file changed since it was checked (%1 bytes, were %2): check it again</source>
            <translation>die Datei des Programms hat sich seit der Prüfung geändert (%1 Bytes, waren %2): erneut prüfen</translation>
        </message>
        <message>
            <source>the program's file changed since it was checked: check it again</source>
            <translation>die Datei des Programms hat sich seit der Prüfung geändert: erneut prüfen</translation>
        </message>
        <message>
            <source>internal: the pass reads back lines it has not finished</source>
            <translation>intern: der Durchgang liest Zeilen zurück, die er noch nicht fertig gelesen hat</translation>
        </message>
        <message>
            <source>the program's file changed since it was checked (lines %1..%2 differ): check it again</source>
            <translation>die Datei des Programms hat sich seit der Prüfung geändert (Zeilen %1..%2 weichen ab): erneut prüfen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramRules</name>
        <message>
            <source>its setup is incomplete, so it refuses every move: write %1 on the Setup page first</source>
            <translation>ihr Setup ist unvollständig, daher lehnt sie jede Fahrt ab: zuerst %1 auf der Seite Setup schreiben</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramRunner</name>
        <message>
            <source>idle</source>
            <translation>bereit</translation>
        </message>
        <message>
            <source>running</source>
            <translation>läuft</translation>
        </message>
        <message>
            <source>paused</source>
            <translation>angehalten</translation>
        </message>
        <message>
            <source>stopping</source>
            <translation>wird gestoppt</translation>
        </message>
        <message>
            <source>finished</source>
            <translation>beendet</translation>
        </message>
        <message>
            <source>failed</source>
            <translation>fehlgeschlagen</translation>
        </message>
        <message>
            <source>aborted</source>
            <translation>abgebrochen</translation>
        </message>
        <message>
            <source>aborted; the controllers did not confirm standstill</source>
            <translation>abgebrochen; die Steuerungen haben den Stillstand nicht bestätigt</translation>
        </message>
        <message>
            <source>a program runs already</source>
            <translation>es läuft bereits ein Programm</translation>
        </message>
        <message>
            <source>%1 has no stop command: the move under way finishes by itself</source>
            <translation>%1 hat keinen Stoppbefehl: die laufende Bewegung endet von selbst</translation>
        </message>
        <message>
            <source>line %1: %2</source>
            <translation>Zeile %1: %2</translation>
        </message>
        <message>
            <source>%1: the machine has nothing to switch</source>
            <translation>%1: die Maschine hat nichts zu schalten</translation>
        </message>
        <message>
            <source>controller "%1": %2</source>
            <translation>Steuerung „%1“: %2</translation>
        </message>
        <message>
            <source>aborted after the move under way ended</source>
            <translation>abgebrochen, nachdem die laufende Bewegung geendet hat</translation>
        </message>
        <message>
            <source>the check was cancelled</source>
            <translation>die Prüfung wurde abgebrochen</translation>
        </message>
        <message>
            <source>the program's file changed: check it again</source>
            <translation>die Datei des Programms hat sich geändert: erneut prüfen</translation>
        </message>
        <message>
            <source>the machine changed while the program was checked (a position, an offset, a tool or a parameter): run it again to check it anew</source>
            <translation>die Maschine hat sich geändert, während das Programm geprüft wurde (eine Position, ein Nullpunkt, ein Werkzeug oder ein Parameter): erneut starten, um es neu zu prüfen</translation>
        </message>
        <message>
            <source>Feed hold: the path stops where it is; Resume goes on from there</source>
            <translation>Vorschub-Halt: Die Bahn bleibt stehen, wo sie ist; Fortsetzen fährt von dort weiter</translation>
        </message>
        <message>
            <source>the run holds in the middle of a contour (feed hold), where new offsets cannot start: put them back to resume, or stop</source>
            <translation>der Lauf hält mitten in einer Kontur (Vorschub-Halt), wo neue Nullpunkte nicht beginnen können: zum Fortsetzen zurücksetzen oder stoppen</translation>
        </message>
        <message>
            <source>the run holds in the middle of an arc or a drilling cycle, where new offsets cannot start: put them back to resume, or stop</source>
            <translation>der Lauf hält mitten in einem Bogen oder Bohrzyklus, wo neue Nullpunkte nicht beginnen können: zum Fortsetzen zurücksetzen oder stoppen</translation>
        </message>
        <message>
            <source>a G92 offset is in effect, which a check of the rest cannot follow: put the offsets back to resume, or stop</source>
            <translation>ein G92-Versatz ist aktiv, dem eine Prüfung des Rests nicht folgen kann: zum Fortsetzen die Nullpunkte zurücksetzen oder stoppen</translation>
        </message>
        <message>
            <source>the machine changed while the rest was checked: resume again to check it anew</source>
            <translation>die Maschine hat sich während der Prüfung des Rests geändert: erneut fortsetzen, um neu zu prüfen</translation>
        </message>
        <message>
            <source>the rest of the program fails its check with them, line %1: %2</source>
            <translation>der Rest des Programms besteht die Prüfung damit nicht, Zeile %1: %2</translation>
        </message>
        <message>
            <source>Not resumed: the offsets or tools changed while the run held; %1</source>
            <translation>Nicht fortgesetzt: Nullpunkte oder Werkzeuge änderten sich während des Halts; %1</translation>
        </message>
        <message>
            <source>The rest of the program runs with the new offsets and tools (checked from line %1).</source>
            <translation>Der Rest des Programms läuft mit den neuen Nullpunkten und Werkzeugen (geprüft ab Zeile %1).</translation>
        </message>
        <message>
            <source>The new offsets and tools are taken; no move is left to run.</source>
            <translation>Die neuen Nullpunkte und Werkzeuge sind übernommen; keine Bewegung bleibt übrig.</translation>
        </message>
        <message>
            <source>the run holds on its way to the start point of the line it runs from, which new offsets would move: put them back to resume, or stop</source>
            <translation>der Lauf hält auf dem Weg zum Startpunkt der Zeile, ab der er läuft, den neue Verschiebungen verschieben würden: sie zurücksetzen, um fortzusetzen, oder stoppen</translation>
        </message>
        <message>
            <source>%1, then set the work Z for it (Zero Z)</source>
            <translation>%1, dann Z dafür nullen</translation>
        </message>
        <message>
            <source>Not resumed: tool %1 takes its length from a touch-off, and the work Z of %2 was not set since the run held: set it for tool %1 (Zero Z on the position display)</source>
            <translation>Nicht fortgesetzt: Werkzeug %1 erhält seine Länge durch Antasten, und der Werkstück-Nullpunkt von Z in %2 wurde seit dem Halt nicht gesetzt: ihn für Werkzeug %1 setzen (Z nullen in der Positionsanzeige)</translation>
        </message>
        <message>
            <source>; or, with the tool Z was set for still in, resume keeping Z</source>
            <translation>; oder, wenn noch das Werkzeug eingesetzt ist, für das Z gesetzt wurde, mit „Z behalten“ fortsetzen</translation>
        </message>
        <message>
            <source>Not resumed keeping Z: tool %1 follows tool %2, whose length it does not have: set the work Z for tool %1 first</source>
            <translation>Nicht mit Z fortgesetzt: Werkzeug %1 folgt auf Werkzeug %2, dessen Länge es nicht hat: zuerst den Werkstück-Nullpunkt von Z für Werkzeug %1 setzen</translation>
        </message>
        <message>
            <source>a program runs</source>
            <translation>ein Programm läuft</translation>
        </message>
        <message>
            <source>Not resumed: the axes are being jogged; let go of the jog first</source>
            <translation>Nicht fortgesetzt: die Achsen werden im Tippbetrieb verfahren; zuerst das Tippen loslassen</translation>
        </message>
        <message>
            <source>Not resumed: the axes are still moving; resume once they stand</source>
            <translation>Nicht fortgesetzt: die Achsen bewegen sich noch; fortsetzen, sobald sie stehen</translation>
        </message>
        <message>
            <source>the run holds under cutter compensation (G41/G42), whose path new offsets or tools would move: put them back to resume, or stop</source>
            <translation>der Lauf hält unter Werkzeugradiuskorrektur (G41/G42), deren Bahn neue Verschiebungen oder Werkzeuge verschieben würden: zum Fortsetzen zurückstellen oder stoppen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ProgramSourceReader</name>
        <message>
            <source>cannot read %1</source>
            <translation>%1 kann nicht gelesen werden</translation>
        </message>
        <message>
            <source>cannot read %1: %2</source>
            <translation>%1 kann nicht gelesen werden: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::RunFromState</name>
        <message>
            <source>spindle on at S%1 (%2)</source>
            <translation>Spindel ein mit S%1 (%2)</translation>
        </message>
        <message>
            <source>coolant on (%1)</source>
            <translation>Kühlmittel ein (%1)</translation>
        </message>
        <message>
            <source>tool %1 loaded</source>
            <translation>Werkzeug %1 eingesetzt</translation>
        </message>
        <message>
            <source>%1 to %2</source>
            <translation>%1 nach %2</translation>
        </message>
        <message>
            <source>%1 up to %2</source>
            <translation>%1 hoch auf %2</translation>
        </message>
        <message>
            <source>%1 down to %2</source>
            <translation>%1 runter auf %2</translation>
        </message>
        <message>
            <source>%1, then %2</source>
            <translation>%1, dann %2</translation>
        </message>
        <message>
            <source>%1 at rapid</source>
            <translation>%1 im Eilgang</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::program::ToolTable</name>
        <message>
            <source>%1 is not a column of a tool table (T, P, Z, D, ...)</source>
            <translation>%1 ist keine Spalte einer Werkzeugtabelle (T, P, Z, D, ...)</translation>
        </message>
        <message>
            <source>%1: T takes a tool number, whole, 0..%2</source>
            <translation>%1: T nimmt eine Werkzeugnummer, ganzzahlig, 0..%2</translation>
        </message>
        <message>
            <source>%1: a diameter is not below 0</source>
            <translation>%1: Ein Durchmesser ist nicht kleiner als 0</translation>
        </message>
        <message>
            <source>the line names no tool (T)</source>
            <translation>die Zeile nennt kein Werkzeug (T)</translation>
        </message>
        <message>
            <source>tool %1 is in the table twice</source>
            <translation>Werkzeug %1 steht zweimal in der Tabelle</translation>
        </message>
        <message>
            <source>the table has more than %1 tools</source>
            <translation>die Tabelle hat mehr als %1 Werkzeuge</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::AxesTable</name>
        <message>
            <source>Name</source>
            <translation>Name</translation>
        </message>
        <message>
            <source>Controller</source>
            <translation>Steuerung</translation>
        </message>
        <message>
            <source>Axis</source>
            <translation>Achse</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Einheit</translation>
        </message>
        <message>
            <source>Steps/unit</source>
            <translation>Schritte/Einheit</translation>
        </message>
        <message>
            <source>Invert</source>
            <translation>Umkehren</translation>
        </message>
        <message>
            <source>Min</source>
            <translation>Min</translation>
        </message>
        <message>
            <source>Max</source>
            <translation>Max</translation>
        </message>
        <message>
            <source>Max jog/s</source>
            <translation>Max. Tippen/s</translation>
        </message>
        <message>
            <source>Ref. direction</source>
            <translation>Ref.-Richtung</translation>
        </message>
        <message>
            <source>Ref. order</source>
            <translation>Ref.-Reihenfolge</translation>
        </message>
        <message>
            <source>Soft limit minimum (optional)</source>
            <translation>Software-Endlage Minimum (optional)</translation>
        </message>
        <message>
            <source>Soft limit maximum (optional)</source>
            <translation>Software-Endlage Maximum (optional)</translation>
        </message>
        <message>
            <source>Jog speed ceiling in unit/s (optional)</source>
            <translation>Höchste Tippgeschwindigkeit in Einheit/s (optional)</translation>
        </message>
        <message>
            <source>Axes with a lower order are referenced first</source>
            <translation>Achsen mit kleinerer Reihenfolge werden zuerst referenziert</translation>
        </message>
        <message>
            <source>A positive machine move is a negative controller move</source>
            <translation>Eine positive Maschinenbewegung ist eine negative Bewegung der Steuerung</translation>
        </message>
        <message>
            <source>default</source>
            <translation>Vorgabe</translation>
        </message>
        <message>
            <source>Jog accel./s²</source>
            <translation>Tipp-Beschl./s²</translation>
        </message>
        <message>
            <source>Jog acceleration in unit/s² (optional; empty: a release from the max jog speed stops within 1 mm or 1 deg)</source>
            <translation>Tippbeschleunigung in Einheit/s² (optional; leer: nach dem Loslassen aus der maximalen Tippgeschwindigkeit steht die Achse innerhalb von 1 mm bzw. 1°)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::AxisListBar</name>
        <message>
            <source>Moving first</source>
            <translation>Bewegte zuerst</translation>
        </message>
        <message>
            <source>Filter: name or address</source>
            <translation>Filter: Name oder Adresse</translation>
        </message>
        <message>
            <source>Shows the drives whose name or bus address contains this text.</source>
            <translation>Zeigt die Antriebe, deren Name oder Busadresse diesen Text enthält.</translation>
        </message>
        <message>
            <source>Lists the drives that move now above the others.</source>
            <translation>Listet die Antriebe, die sich gerade bewegen, über den anderen.</translation>
        </message>
        <message>
            <source>%1 of %2</source>
            <translation>%1 von %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::AxisStatusList</name>
        <message>
            <source>Axes</source>
            <translation>Achsen</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::AxisStatusModel</name>
        <message>
            <source>%1 ✖ silent</source>
            <translation>%1 ✖ stumm</translation>
        </message>
        <message>
            <source>Axis</source>
            <translation>Achse</translation>
        </message>
        <message>
            <source>Moving</source>
            <translation>Fährt</translation>
        </message>
        <message>
            <source>Jog</source>
            <translation>Tippen</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Endschalter</translation>
        </message>
        <message>
            <source>Ref. switch</source>
            <translation>Ref.-Schalter</translation>
        </message>
        <message>
            <source>Referenced</source>
            <translation>Referenziert</translation>
        </message>
        <message>
            <source>Position</source>
            <translation>Position</translation>
        </message>
        <message>
            <source>Drive</source>
            <translation>Antrieb</translation>
        </message>
        <message>
            <source>Positioning, feed, reference or velocity move</source>
            <translation>Positionier-, Vorschub-, Referenz- oder Geschwindigkeitsfahrt</translation>
        </message>
        <message>
            <source>Jogging at a non-zero rate</source>
            <translation>Tippbetrieb mit einer Rate ungleich null</translation>
        </message>
        <message>
            <source>A limit switch of this axis is active</source>
            <translation>Ein Endschalter dieser Achse ist aktiv</translation>
        </message>
        <message>
            <source>The reference switch is active</source>
            <translation>Der Referenzschalter ist aktiv</translation>
        </message>
        <message>
            <source>Referenced since the last panic, reset or reconnect</source>
            <translation>Referenziert seit dem letzten Panik-Stopp, Reset oder Neuverbinden</translation>
        </message>
        <message>
            <source>Estimated from the commanded rates, not read back.</source>
            <translation>Aus den vorgegebenen Geschwindigkeiten geschätzt, nicht zurückgelesen.</translation>
        </message>
        <message>
            <source>Not referenced: the count is not tied to the machine's zero.</source>
            <translation>Nicht referenziert: die Zählung ist nicht an den Nullpunkt der Maschine gebunden.</translation>
        </message>
        <message>
            <source>The drive stopped answering; check its power, address and the RS485 wiring. The other drives keep working.</source>
            <translation>Der Antrieb antwortet nicht mehr; Versorgung, Adresse und RS485-Verdrahtung prüfen. Die anderen Antriebe arbeiten weiter.</translation>
        </message>
        <message>
            <source>Referenced: the count is tied to the machine's zero.</source>
            <translation>Referenziert: die Zählung ist an den Nullpunkt der Maschine gebunden.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ChartsPanel</name>
        <message>
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>%1 s</source>
            <translation>%1 s</translation>
        </message>
        <message>
            <source>%1 min</source>
            <translation>%1 min</translation>
        </message>
        <message>
            <source>Export CSV…</source>
            <translation>CSV exportieren…</translation>
        </message>
        <message>
            <source>Export PNG…</source>
            <translation>PNG exportieren…</translation>
        </message>
        <message>
            <source>Time window:</source>
            <translation>Zeitfenster:</translation>
        </message>
        <message>
            <source>time [s]</source>
            <translation>Zeit [s]</translation>
        </message>
        <message>
            <source>Position</source>
            <translation>Position</translation>
        </message>
        <message>
            <source>Commanded velocity</source>
            <translation>Vorgegebene Geschwindigkeit</translation>
        </message>
        <message>
            <source>Temperature</source>
            <translation>Temperatur</translation>
        </message>
        <message>
            <source>Poll rate</source>
            <translation>Abfragerate</translation>
        </message>
        <message>
            <source>Hz</source>
            <translation>Hz</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>%1 kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>Cannot write %1</source>
            <translation>%1 kann nicht geschrieben werden</translation>
        </message>
        <message>
            <source>Export CSV</source>
            <translation>CSV exportieren</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV-Dateien (*.csv)</translation>
        </message>
        <message>
            <source>Export PNG</source>
            <translation>PNG exportieren</translation>
        </message>
        <message>
            <source>PNG images (*.png)</source>
            <translation>PNG-Bilder (*.png)</translation>
        </message>
        <message>
            <source>°C</source>
            <translation>°C</translation>
        </message>
        <message>
            <source>%1/s</source>
            <translation>%1/s</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ClosedLoopPanel</name>
        <message>
            <source>Closed loop (manual 8.1)</source>
            <translation>Regelung (Handbuch 8.1)</translation>
        </message>
        <message>
            <source>1 Check motor data</source>
            <translation>1 Motordaten prüfen</translation>
        </message>
        <message>
            <source>Read pole pairs, encoder increments and revolutions, the encoder position and whether closed loop is on; nothing moves</source>
            <translation>Polpaare, Encoderinkremente und -umdrehungen, Encoderposition und den Zustand der Regelung lesen; nichts bewegt sich</translation>
        </message>
        <message>
            <source>2 Calibration run…</source>
            <translation>2 Kalibrierfahrt…</translation>
        </message>
        <message>
            <source>Mode 101: once for every newly connected motor, also of the same type. The motor turns.</source>
            <translation>Modus 101: einmal für jeden neu angeschlossenen Motor, auch gleichen Typs. Der Motor dreht sich.</translation>
        </message>
        <message>
            <source>3 Reference run…</source>
            <translation>3 Referenzfahrt…</translation>
        </message>
        <message>
            <source>Mode 8: after every power-on, before closed loop can be switched on. The motor turns.</source>
            <translation>Modus 8: nach jedem Einschalten, bevor die Regelung eingeschaltet werden kann. Der Motor dreht sich.</translation>
        </message>
        <message>
            <source>4 Closed loop on…</source>
            <translation>4 Regelung ein…</translation>
        </message>
        <message>
            <source>Switch closed loop on and read it back; the drive ignores it without the reference run since power-on</source>
            <translation>Regelung einschalten und zurücklesen; ohne Referenzfahrt seit dem Einschalten ignoriert der Antrieb das</translation>
        </message>
        <message>
            <source>Off</source>
            <translation>Aus</translation>
        </message>
        <message>
            <source>Switch closed loop off and read it back</source>
            <translation>Regelung ausschalten und zurücklesen</translation>
        </message>
        <message>
            <source>Reset position error</source>
            <translation>Positionsfehler zurücksetzen</translation>
        </message>
        <message>
            <source>Clear the drive's position error; its position becomes the encoder's (manual 5.14)</source>
            <translation>Den Positionsfehler des Antriebs löschen; seine Position wird die des Encoders (Handbuch 5.14)</translation>
        </message>
        <message>
            <source>The drive (axis) to commission</source>
            <translation>Der Antrieb (die Achse), der in Betrieb genommen wird</translation>
        </message>
        <message>
            <source>+ (d=1)</source>
            <translation>+ (d=1)</translation>
        </message>
        <message>
            <source>− (d=0)</source>
            <translation>− (d=0)</translation>
        </message>
        <message>
            <source>Direction of the reference run ('d', manual 6.12)</source>
            <translation>Richtung der Referenzfahrt ('d', Handbuch 6.12)</translation>
        </message>
        <message>
            <source>Drive:</source>
            <translation>Antrieb:</translation>
        </message>
        <message>
            <source>not checked in this connection</source>
            <translation>in dieser Verbindung nicht geprüft</translation>
        </message>
        <message>
            <source>Calibration run</source>
            <translation>Kalibrierfahrt</translation>
        </message>
        <message>
            <source>The calibration run (mode 101) of axis %1 turns the motor. Let the shaft turn freely; STOP and PANIC end the run at once.

Manual 8.1: a calibration run is needed every time a motor is connected, even one of the same type. Pole pairs, encoder increments and revolutions must match the motor: otherwise closed loop can speed the motor up beyond its mechanical limits.

Start the calibration run now?</source>
            <translation>Die Kalibrierfahrt (Modus 101) von Achse %1 dreht den Motor. Die Welle muss frei drehen können; STOPP und PANIK beenden die Fahrt sofort.

Handbuch 8.1: Jedes Mal, wenn ein Motor angeschlossen wird, auch einer gleichen Typs, ist eine Kalibrierfahrt nötig. Polpaare, Encoderinkremente und -umdrehungen müssen zum Motor passen, sonst kann die Regelung den Motor über seine mechanische Belastbarkeit hinaus hochdrehen.

Kalibrierfahrt jetzt starten?</translation>
        </message>
        <message>
            <source>Closed-loop reference run</source>
            <translation>Regelungs-Referenzfahrt</translation>
        </message>
        <message>
            <source>The closed-loop reference run (mode 8) of axis %1 turns the motor in the direction %2 until the encoder's index mark. STOP and PANIC end it at once.

Manual 8.1: closed loop can only be switched on after this run since the drive was switched on.

Start the reference run now?</source>
            <translation>Die Regelungs-Referenzfahrt (Modus 8) von Achse %1 dreht den Motor in Richtung %2 bis zum Indexstrich des Encoders. STOPP und PANIK beenden sie sofort.

Handbuch 8.1: Die Regelung lässt sich erst einschalten, wenn diese Fahrt seit dem Einschalten des Antriebs gelaufen ist.

Referenzfahrt jetzt starten?</translation>
        </message>
        <message>
            <source>Closed loop on</source>
            <translation>Regelung ein</translation>
        </message>
        <message>
            <source>ATTENTION (manual 8.1): if pole pairs or encoder data do not match the motor, or this motor was never calibrated on this drive, closed loop can speed the motor up beyond its mechanical limits.

Switch closed loop on for axis %1?</source>
            <translation>ACHTUNG (Handbuch 8.1): Passen Polpaare oder Encoderdaten nicht zum Motor oder wurde dieser Motor an diesem Antrieb nie kalibriert, kann die Regelung den Motor über seine mechanische Belastbarkeit hinaus hochdrehen.

Regelung für Achse %1 einschalten?</translation>
        </message>
        <message>
            <source>running…</source>
            <translation>läuft…</translation>
        </message>
        <message>
            <source>done in this connection</source>
            <translation>in dieser Verbindung erledigt</translation>
        </message>
        <message>
            <source>FAILED: the drive reported an error</source>
            <translation>FEHLGESCHLAGEN: der Antrieb hat einen Fehler gemeldet</translation>
        </message>
        <message>
            <source>aborted: not complete</source>
            <translation>abgebrochen: nicht vollständig</translation>
        </message>
        <message>
            <source>not run in this connection (the drive cannot report it)</source>
            <translation>in dieser Verbindung nicht gelaufen (der Antrieb kann es nicht melden)</translation>
        </message>
        <message>
            <source>ended after %1 s: position %2, encoder %3 (read back)</source>
            <translation>beendet nach %1 s: Position %2, Encoder %3 (zurückgelesen)</translation>
        </message>
        <message>
            <source>Calibration run done.</source>
            <translation>Kalibrierfahrt erledigt.</translation>
        </message>
        <message>
            <source>Reference run done: the axis is referenced.</source>
            <translation>Referenzfahrt erledigt: die Achse ist referenziert.</translation>
        </message>
        <message>
            <source>Closed loop is on (read back).</source>
            <translation>Regelung ist eingeschaltet (zurückgelesen).</translation>
        </message>
        <message>
            <source>Closed loop is off (read back).</source>
            <translation>Regelung ist ausgeschaltet (zurückgelesen).</translation>
        </message>
        <message>
            <source>Position error cleared; the position is the encoder's now.</source>
            <translation>Positionsfehler gelöscht; die Position ist jetzt die des Encoders.</translation>
        </message>
        <message>
            <source>pole pairs %1, encoder %2 increments per %3 revolution(s), step angle %4°; encoder position %5, position %6</source>
            <translation>Polpaare %1, Encoder %2 Inkremente je %3 Umdrehung(en), Schrittwinkel %4°; Encoderposition %5, Position %6</translation>
        </message>
        <message>
            <source>CANNOT WORK: %1 (%2)</source>
            <translation>FUNKTIONIERT NICHT: %1 (%2)</translation>
        </message>
        <message>
            <source>unknown: not read in this connection</source>
            <translation>unbekannt: in dieser Verbindung nicht gelesen</translation>
        </message>
        <message>
            <source>on (read back)</source>
            <translation>ein (zurückgelesen)</translation>
        </message>
        <message>
            <source>off (read back)</source>
            <translation>aus (zurückgelesen)</translation>
        </message>
        <message>
            <source>not read yet</source>
            <translation>noch nicht gelesen</translation>
        </message>
        <message>
            <source>calibration run: %1 s, position %2, encoder %3</source>
            <translation>Kalibrierfahrt: %1 s, Position %2, Encoder %3</translation>
        </message>
        <message>
            <source>reference run: %1 s, position %2, encoder %3</source>
            <translation>Referenzfahrt: %1 s, Position %2, Encoder %3</translation>
        </message>
        <message>
            <source>Connect, then check the motor data.</source>
            <translation>Verbinden, dann die Motordaten prüfen.</translation>
        </message>
        <message>
            <source>Next: 1, check the motor data.</source>
            <translation>Als Nächstes: 1, die Motordaten prüfen.</translation>
        </message>
        <message>
            <source>Correct the motor data first (Setup, closed loop).</source>
            <translation>Zuerst die Motordaten korrigieren (Einrichtung, Regelung).</translation>
        </message>
        <message>
            <source>Next: 2, the calibration run again (is the encoder connected?).</source>
            <translation>Als Nächstes: 2, die Kalibrierfahrt wiederholen (ist der Encoder angeschlossen?).</translation>
        </message>
        <message>
            <source>Next: 2, the calibration run for a newly connected motor; else 3.</source>
            <translation>Als Nächstes: 2, die Kalibrierfahrt für einen neu angeschlossenen Motor; sonst 3.</translation>
        </message>
        <message>
            <source>Next: 3, the reference run.</source>
            <translation>Als Nächstes: 3, die Referenzfahrt.</translation>
        </message>
        <message>
            <source>Next: 4, closed loop on.</source>
            <translation>Als Nächstes: 4, Regelung ein.</translation>
        </message>
        <message>
            <source>Closed loop is on.</source>
            <translation>Die Regelung ist eingeschaltet.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ConnectionBar</name>
        <message>
            <source>Connect</source>
            <translation>Verbinden</translation>
        </message>
        <message>
            <source>Controller model</source>
            <translation>Steuerungsmodell</translation>
        </message>
        <message>
            <source>Serial port, the in-process simulator, tcp://HOST:PORT for a serial device server, or a device path such as /dev/pts/3</source>
            <translation>Serielle Schnittstelle, der eingebaute Simulator, tcp://HOST:PORT für einen seriellen Geräteserver oder ein Gerätepfad wie /dev/pts/3</translation>
        </message>
        <message>
            <source>port, tcp://host:port or path</source>
            <translation>Port, tcp://host:port oder Pfad</translation>
        </message>
        <message>
            <source> ms</source>
            <translation> ms</translation>
        </message>
        <message>
            <source>Status poll interval</source>
            <translation>Intervall der Statusabfrage</translation>
        </message>
        <message>
            <source>Achieved status poll rate</source>
            <translation>Erreichte Rate der Statusabfrage</translation>
        </message>
        <message>
            <source>Model:</source>
            <translation>Modell:</translation>
        </message>
        <message>
            <source>Port:</source>
            <translation>Port:</translation>
        </message>
        <message>
            <source>Poll:</source>
            <translation>Abfrage:</translation>
        </message>
        <message>
            <source>Simulator (in-process)</source>
            <translation>Simulator (eingebaut)</translation>
        </message>
        <message>
            <source>Choose a port first.</source>
            <translation>Bitte zuerst einen Port wählen.</translation>
        </message>
        <message>
            <source>Disconnect</source>
            <translation>Trennen</translation>
        </message>
        <message>
            <source>Disconnected</source>
            <translation>Getrennt</translation>
        </message>
        <message>
            <source>Connecting</source>
            <translation>Verbinde</translation>
        </message>
        <message>
            <source>Connected</source>
            <translation>Verbunden</translation>
        </message>
        <message>
            <source>Link lost</source>
            <translation>Verbindung verloren</translation>
        </message>
        <message>
            <source>– Hz</source>
            <translation>– Hz</translation>
        </message>
        <message>
            <source>%1 Hz</source>
            <translation>%1 Hz</translation>
        </message>
        <message>
            <source>No reply since %1</source>
            <translation>Keine Antwort seit %1</translation>
        </message>
        <message>
            <source>Connect failed</source>
            <translation>Verbindung fehlgeschlagen</translation>
        </message>
        <message>
            <source>Reset:</source>
            <translation>Reset:</translation>
        </message>
        <message>
            <source>RTS</source>
            <translation>RTS</translation>
        </message>
        <message>
            <source>DTR</source>
            <translation>DTR</translation>
        </message>
        <message>
            <source>The modem line wired to the controller's reset input</source>
            <translation>Die Modemleitung, die mit dem Reset-Eingang der Steuerung verbunden ist</translation>
        </message>
        <message>
            <source>Recent ports and reconnect options</source>
            <translation>Zuletzt benutzte Ports und Optionen zum Wiederverbinden</translation>
        </message>
        <message>
            <source>Connection options</source>
            <translation>Verbindungsoptionen</translation>
        </message>
        <message>
            <source>Recent ports</source>
            <translation>Zuletzt benutzte Ports</translation>
        </message>
        <message>
            <source>Reconnect when the USB device returns</source>
            <translation>Wieder verbinden, wenn das USB-Gerät zurückkommt</translation>
        </message>
        <message>
            <source>When the USB adapter of a lost link is plugged in again (same vendor, product and serial number), connect again. Positions count as unknown afterwards and nothing resumes by itself.</source>
            <translation>Wird der USB-Adapter einer verlorenen Verbindung wieder eingesteckt (gleicher Hersteller, gleiches Produkt, gleiche Seriennummer), wird wieder verbunden. Die Positionen gelten danach als unbekannt, und nichts läuft von selbst weiter.</translation>
        </message>
        <message>
            <source>(none yet)</source>
            <translation>(noch keine)</translation>
        </message>
        <message>
            <source>Reconnected to %1: the USB device came back. Positions are unknown until the axes are referenced; nothing was resumed (no jog, move or bridge).</source>
            <translation>Wieder verbunden mit %1: Das USB-Gerät ist zurück. Die Positionen sind unbekannt, bis die Achsen referenziert sind; nichts wurde fortgesetzt (kein Joggen, keine Fahrt, keine Brücke).</translation>
        </message>
        <message>
            <source>no status poll</source>
            <translation>keine Statusabfrage</translation>
        </message>
        <message>
            <source>This protocol has no status request: the controller reports only by itself (after a move, at a switch or the door). Silence on an idle link is normal and is not checked.</source>
            <translation>Dieses Protokoll kennt keine Statusabfrage: Die Steuerung meldet sich nur von selbst (nach einer Fahrt, an einem Schalter oder an der Tür). Stille auf einer ruhenden Verbindung ist normal und wird nicht geprüft.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ControllersTable</name>
        <message>
            <source>Id</source>
            <translation>Kennung</translation>
        </message>
        <message>
            <source>Model</source>
            <translation>Modell</translation>
        </message>
        <message>
            <source>Port</source>
            <translation>Port</translation>
        </message>
        <message>
            <source>Bus addresses</source>
            <translation>Busadressen</translation>
        </message>
        <message>
            <source>Reset line</source>
            <translation>Reset-Leitung</translation>
        </message>
        <message>
            <source>/dev/ttyUSB0, tcp://…, sim</source>
            <translation>/dev/ttyUSB0, tcp://…, sim</translation>
        </message>
        <message>
            <source>default</source>
            <translation>Vorgabe</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keine</translation>
        </message>
        <message>
            <source>Setup file</source>
            <translation>Einrichtungsdatei</translation>
        </message>
        <message>
            <source>A parameter file (as Export writes it), relative to the machine file's folder: written to the controller on every connect</source>
            <translation>Eine Parameterdatei (wie Export sie schreibt), relativ zum Ordner der Maschinendatei: bei jedem Verbinden in die Steuerung geschrieben</translation>
        </message>
        <message>
            <source>Controller axis = bus address, e.g. X=1 Y=2 or feeder=5 gate=6 (names: a letter, then letters, digits or _; empty: X=1, Y=2, Z=3)</source>
            <translation>Steuerungsachse = Busadresse, z. B. X=1 Y=2 oder feeder=5 gate=6 (Namen: ein Buchstabe, dann Buchstaben, Ziffern oder _; leer: X=1, Y=2, Z=3)</translation>
        </message>
        <message>
            <source>write controller axis = bus address, like X=1 Y=2 or feeder=5 (is "%1": %2)</source>
            <translation>Steuerungsachse = Busadresse schreiben, etwa X=1 Y=2 oder feeder=5 (ist „%1“: %2)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::DemoMachine</name>
        <message>
            <source>Cannot write the demo file %1: %2</source>
            <translation>Die Demo-Datei %1 kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>Cannot create the demo folder %1</source>
            <translation>Der Demo-Ordner %1 kann nicht angelegt werden</translation>
        </message>
        <message>
            <source>Cannot open the demo program %1</source>
            <translation>Das Demo-Programm %1 kann nicht geöffnet werden</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::DiffDialog</name>
        <message>
            <source>(not set)</source>
            <translation>(nicht gesetzt)</translation>
        </message>
        <message>
            <source>on</source>
            <translation>ein</translation>
        </message>
        <message>
            <source>off</source>
            <translation>aus</translation>
        </message>
        <message>
            <source>Load parameters</source>
            <translation>Parameter laden</translation>
        </message>
        <message>
            <source>Parameter</source>
            <translation>Parameter</translation>
        </message>
        <message>
            <source>Axis</source>
            <translation>Achse</translation>
        </message>
        <message>
            <source>Form</source>
            <translation>Formular</translation>
        </message>
        <message>
            <source>File</source>
            <translation>Datei</translation>
        </message>
        <message>
            <source>%1 holds the same values as the form.</source>
            <translation>%1 enthält dieselben Werte wie das Formular.</translation>
        </message>
        <message numerus="yes">
            <source>%1 changes %n value(s) (highlighted).</source>
            <translation>
                <numerusform>%1 ändert %n Wert (hervorgehoben).</numerusform>
                <numerusform>%1 ändert %n Werte (hervorgehoben).</numerusform>
            </translation>
        </message>
        <message>
            <source>Load into form</source>
            <translation>Ins Formular laden</translation>
        </message>
        <message>
            <source>Load and write</source>
            <translation>Laden und schreiben</translation>
        </message>
        <message>
            <source>Changes only</source>
            <translation>Nur Änderungen</translation>
        </message>
        <message>
            <source>Hide the values the file leaves as they are</source>
            <translation>Werte ausblenden, die die Datei nicht ändert</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::DigitalIoGroup</name>
        <message>
            <source>Inputs and outputs</source>
            <translation>Ein- und Ausgänge</translation>
        </message>
        <message>
            <source>Inputs:</source>
            <translation>Eingänge:</translation>
        </message>
        <message>
            <source>Input %1: level as last read (lit: high)</source>
            <translation>Eingang %1: zuletzt gelesener Pegel (leuchtet: High)</translation>
        </message>
        <message>
            <source>Outputs:</source>
            <translation>Ausgänge:</translation>
        </message>
        <message>
            <source>on</source>
            <translation>ein</translation>
        </message>
        <message>
            <source>off</source>
            <translation>aus</translation>
        </message>
        <message>
            <source>Output %1: on; click to switch it off</source>
            <translation>Ausgang %1: ein; klicken, um ihn auszuschalten</translation>
        </message>
        <message>
            <source>Output %1: off; click to switch it on</source>
            <translation>Ausgang %1: aus; klicken, um ihn einzuschalten</translation>
        </message>
        <message>
            <source>Output %1: state unknown (not switched in this session; the controller cannot report it); click to switch it on</source>
            <translation>Ausgang %1: Zustand unbekannt (in dieser Sitzung nicht geschaltet; die Steuerung kann ihn nicht melden); klicken, um ihn einzuschalten</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::DocumentationDialog</name>
        <message>
            <source>Overview and quick start</source>
            <translation>Überblick und Schnellstart (englisch)</translation>
        </message>
        <message>
            <source>Machines</source>
            <translation>Maschinen (englisch)</translation>
        </message>
        <message>
            <source>Programs (G-code)</source>
            <translation>Programme (G-Code, englisch)</translation>
        </message>
        <message>
            <source>Command line</source>
            <translation>Kommandozeile (englisch)</translation>
        </message>
        <message>
            <source>StepDeck documentation</source>
            <translation>StepDeck-Dokumentation</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::DriveListModel</name>
        <message>
            <source>✔ yes</source>
            <translation>✔ ja</translation>
        </message>
        <message>
            <source>✖ NOT RESPONDING</source>
            <translation>✖ ANTWORTET NICHT</translation>
        </message>
        <message>
            <source>The drive stopped answering; check its power, address and the RS485 wiring. The other drives keep working.</source>
            <translation>Der Antrieb antwortet nicht mehr; Versorgung, Adresse und RS485-Verdrahtung prüfen. Die anderen Antriebe arbeiten weiter.</translation>
        </message>
        <message>
            <source>Address</source>
            <translation>Adresse</translation>
        </message>
        <message>
            <source>Axes</source>
            <translation>Achsen</translation>
        </message>
        <message>
            <source>Responding</source>
            <translation>Antwortet</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>State</source>
            <translation>Zustand</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::DrivePanel</name>
        <message>
            <source>Address</source>
            <translation>Adresse</translation>
        </message>
        <message>
            <source>Firmware</source>
            <translation>Firmware</translation>
        </message>
        <message>
            <source>Hardware</source>
            <translation>Hardware</translation>
        </message>
        <message>
            <source>Date</source>
            <translation>Datum</translation>
        </message>
        <message>
            <source>Scan bus</source>
            <translation>Bus durchsuchen</translation>
        </message>
        <message>
            <source>Drives of this machine</source>
            <translation>Antriebe dieser Maschine</translation>
        </message>
        <message>
            <source>Scan failed: %1</source>
            <translation>Suche fehlgeschlagen: %1</translation>
        </message>
        <message numerus="yes">
            <source>%n drive(s) found</source>
            <translation>
                <numerusform>%n Antrieb gefunden</numerusform>
                <numerusform>%n Antriebe gefunden</numerusform>
            </translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
        <message>
            <source>Stop the scan after the addresses being asked now</source>
            <translation>Die Suche nach den gerade abgefragten Adressen beenden</translation>
        </message>
        <message>
            <source>Scanning addresses %1..%2 (%3..%4 now)…</source>
            <translation>Suche Adressen %1..%2 (jetzt %3..%4)…</translation>
        </message>
        <message numerus="yes">
            <source>Scan cancelled after address %1: %n drive(s) found</source>
            <translation>
                <numerusform>Suche nach Adresse %1 abgebrochen: %n Antrieb gefunden</numerusform>
                <numerusform>Suche nach Adresse %1 abgebrochen: %n Antriebe gefunden</numerusform>
            </translation>
        </message>
        <message>
            <source>Ask every address %1..%2 for its firmware (a few seconds); the drives of this machine keep their status meanwhile</source>
            <translation>Jede Adresse %1..%2 nach ihrer Firmware fragen (einige Sekunden); die Antriebe dieser Maschine behalten währenddessen ihren Status</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::EditorTable</name>
        <message>
            <source>must be a decimal number like 88.8889 (is "%1")</source>
            <translation>muss eine Dezimalzahl wie 88.8889 sein (ist "%1")</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::GamepadJogSource</name>
        <message>
            <source>Gamepad</source>
            <translation>Gamepad</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::GamepadPanel</name>
        <message>
            <source>Dead-man button held</source>
            <translation>Totmanntaste gedrückt</translation>
        </message>
        <message>
            <source>Jog with the gamepad</source>
            <translation>Mit dem Gamepad verfahren</translation>
        </message>
        <message>
            <source>Calibrate</source>
            <translation>Kalibrieren</translation>
        </message>
        <message>
            <source>Button that must be held for the sticks to move the machine</source>
            <translation>Taste, die gedrückt bleiben muss, damit die Sticks die Maschine bewegen</translation>
        </message>
        <message>
            <source>Settings</source>
            <translation>Einstellungen</translation>
        </message>
        <message>
            <source>Dead-man button:</source>
            <translation>Totmanntaste:</translation>
        </message>
        <message>
            <source>Dead zone:</source>
            <translation>Totzone:</translation>
        </message>
        <message>
            <source>Stick mapping</source>
            <translation>Stick-Zuordnung</translation>
        </message>
        <message>
            <source>not used</source>
            <translation>ungenutzt</translation>
        </message>
        <message>
            <source>stick axis %1</source>
            <translation>Stick-Achse %1</translation>
        </message>
        <message>
            <source>invert</source>
            <translation>umkehren</translation>
        </message>
        <message>
            <source>Sticks</source>
            <translation>Sticks</translation>
        </message>
        <message>
            <source>Calibration saved.</source>
            <translation>Kalibrierung gespeichert.</translation>
        </message>
        <message>
            <source>Finish calibration</source>
            <translation>Kalibrierung beenden</translation>
        </message>
        <message>
            <source>Leave the sticks at rest, then move each stick to all its ends and press "Finish calibration". The machine does not move while calibrating.</source>
            <translation>Sticks in Ruhe lassen, dann jeden Stick an alle Anschläge bewegen und „Kalibrierung beenden“ drücken. Während der Kalibrierung bewegt sich die Maschine nicht.</translation>
        </message>
        <message>
            <source>No gamepad support.</source>
            <translation>Keine Gamepad-Unterstützung.</translation>
        </message>
        <message>
            <source>No gamepad connected. Plug one in; it is picked up at once.</source>
            <translation>Kein Gamepad angeschlossen. Einfach einstecken; es wird sofort erkannt.</translation>
        </message>
        <message>
            <source>Connected: %1</source>
            <translation>Verbunden: %1</translation>
        </message>
        <message>
            <source>Axis %1</source>
            <translation>Achse %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::HelpMenu</name>
        <message>
            <source>&amp;Help</source>
            <translation>&amp;Hilfe</translation>
        </message>
        <message>
            <source>&amp;Keyboard shortcuts…</source>
            <translation>&amp;Tastenkürzel…</translation>
        </message>
        <message>
            <source>&amp;Command line…</source>
            <translation>&amp;Kommandozeile…</translation>
        </message>
        <message>
            <source>&amp;About StepDeck</source>
            <translation>&amp;Über StepDeck</translation>
        </message>
        <message>
            <source>About StepDeck</source>
            <translation>Über StepDeck</translation>
        </message>
        <message>
            <source>&lt;b&gt;StepDeck&lt;/b&gt; %1&lt;br&gt;Operator and technician software for stepper-motor controllers.&lt;br&gt;&lt;br&gt;Esc: ramped stop of all motion&lt;br&gt;F1: panic stop (positions are lost)</source>
            <translation>&lt;b&gt;StepDeck&lt;/b&gt; %1&lt;br&gt;Bedien- und Techniker-Software für Schrittmotorsteuerungen.&lt;br&gt;&lt;br&gt;Esc: Stopp aller Bewegungen mit Rampe&lt;br&gt;F1: Panik-Stopp (die Positionen gehen verloren)</translation>
        </message>
        <message>
            <source>About &amp;Qt</source>
            <translation>Über &amp;Qt</translation>
        </message>
        <message>
            <source>About Qt</source>
            <translation>Über Qt</translation>
        </message>
        <message>
            <source>StepDeck uses Qt %1, a cross-platform application framework by The Qt Company, under the GNU LGPL version 3. See &lt;a href="https://www.qt.io/"&gt;qt.io&lt;/a&gt;.</source>
            <translation>StepDeck verwendet Qt %1, ein plattformübergreifendes Anwendungs-Framework von The Qt Company, unter der GNU LGPL Version 3. Siehe &lt;a href="https://www.qt.io/"&gt;qt.io&lt;/a&gt;.</translation>
        </message>
        <message>
            <source>Command line: stepdeck-cli</source>
            <translation>Kommandozeile: stepdeck-cli</translation>
        </message>
        <message>
            <source>&amp;Documentation…</source>
            <translation>&amp;Dokumentation…</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::IncrementalJogWidget</name>
        <message>
            <source>Incremental jog</source>
            <translation>Schrittmaß</translation>
        </message>
        <message>
            <source>Custom</source>
            <translation>Eigener Wert</translation>
        </message>
        <message>
            <source>Step:</source>
            <translation>Schritt:</translation>
        </message>
        <message>
            <source>Move %1 by minus one step size</source>
            <translation>%1 um eine Schrittweite in Minusrichtung verfahren</translation>
        </message>
        <message>
            <source>Move %1 by plus one step size</source>
            <translation>%1 um eine Schrittweite in Plusrichtung verfahren</translation>
        </message>
        <message>
            <source>In each axis' unit (mm, deg or steps)</source>
            <translation>In der Einheit jeder Achse (mm, ° oder Schritte)</translation>
        </message>
        <message>
            <source>Per click of a +/- button, in each axis' unit (mm, deg or steps)</source>
            <translation>Pro Klick auf eine +/−-Taste, in der Einheit jeder Achse (mm, ° oder Schritte)</translation>
        </message>
        <message>
            <source>Incremental jog refused: %1</source>
            <translation>Schrittweises Verfahren abgelehnt: %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::InputProgramsPage</name>
        <message>
            <source>Write to controller</source>
            <translation>In die Steuerung schreiben</translation>
        </message>
        <message>
            <source>Write anyway</source>
            <translation>Trotzdem schreiben</translation>
        </message>
        <message>
            <source>Erase from controller</source>
            <translation>In der Steuerung löschen</translation>
        </message>
        <message>
            <source>e.g. Input 8: vector move X</source>
            <translation>z. B. Eingang 8: Vektorfahrt X</translation>
        </message>
        <message>
            <source>One command per line, e.g.
$H,x
L1,x191
W1500</source>
            <translation>Ein Befehl je Zeile, z. B.
$H,x
L1,x191
W1500</translation>
        </message>
        <message>
            <source>The input carries a reference switch: write only if no switch is wired to it</source>
            <translation>An dem Eingang liegt ein Referenzschalter: nur schreiben, wenn dort kein Schalter angeschlossen ist</translation>
        </message>
        <message>
            <source>Title:</source>
            <translation>Titel:</translation>
        </message>
        <message>
            <source>Commands:</source>
            <translation>Befehle:</translation>
        </message>
        <message>
            <source>The controller cannot read its programs back: the list shows what was written or erased from here.</source>
            <translation>Die Steuerung kann ihre Programme nicht zurücklesen: die Liste zeigt, was von hier aus geschrieben oder gelöscht wurde.</translation>
        </message>
        <message>
            <source>not written from here</source>
            <translation>nicht von hier geschrieben</translation>
        </message>
        <message>
            <source>written %1</source>
            <translation>geschrieben %1</translation>
        </message>
        <message>
            <source>erased %1</source>
            <translation>gelöscht %1</translation>
        </message>
        <message>
            <source>Input %1: %2
%3</source>
            <translation>Eingang %1: %2
%3</translation>
        </message>
        <message>
            <source>(no title)</source>
            <translation>(kein Titel)</translation>
        </message>
        <message>
            <source>Title: printable ASCII only (no umlauts)</source>
            <translation>Titel: nur druckbares ASCII (keine Umlaute)</translation>
        </message>
        <message>
            <source>A program needs at least one command.</source>
            <translation>Ein Programm braucht mindestens einen Befehl.</translation>
        </message>
        <message>
            <source>Line %1: %2</source>
            <translation>Zeile %1: %2</translation>
        </message>
        <message>
            <source>Every command is valid.</source>
            <translation>Alle Befehle sind gültig.</translation>
        </message>
        <message>
            <source>Writing the program of input %1…</source>
            <translation>Das Programm von Eingang %1 wird geschrieben…</translation>
        </message>
        <message>
            <source>Erasing the program of input %1…</source>
            <translation>Das Programm von Eingang %1 wird gelöscht…</translation>
        </message>
        <message>
            <source>The program of input %1 is erased.</source>
            <translation>Das Programm von Eingang %1 ist gelöscht.</translation>
        </message>
        <message>
            <source>The program of input %1 is stored in the controller.</source>
            <translation>Das Programm von Eingang %1 ist in der Steuerung gespeichert.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::JobLayout</name>
        <message>
            <source>Hide jog pad</source>
            <translation>Tippfeld ausblenden</translation>
        </message>
        <message>
            <source>Show jog pad</source>
            <translation>Tippfeld zeigen</translation>
        </message>
        <message>
            <source>Give the jog pad's room to the program's lines and toolpath until the job ends.</source>
            <translation>Den Platz des Tippfelds bis zum Ende des Auftrags den Programmzeilen und der Werkzeugbahn geben.</translation>
        </message>
        <message>
            <source>The job has the jog pad's room. Show it to jog during a hold (a touch-off at a tool change); the keyboard jog works either way.</source>
            <translation>Der Auftrag hat den Platz des Tippfelds. Es zeigen, um während eines Halts zu tippen (Antasten beim Werkzeugwechsel); das Tippen mit der Tastatur geht in jedem Fall.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::JogAxisMap</name>
        <message>
            <source>mm/s</source>
            <translation>mm/s</translation>
        </message>
        <message>
            <source>deg/s</source>
            <translation>°/s</translation>
        </message>
        <message>
            <source>steps/s</source>
            <translation>Schritte/s</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::JogController</name>
        <message>
            <source>Jog refused: not connected</source>
            <translation>Tippbetrieb abgelehnt: nicht verbunden</translation>
        </message>
        <message>
            <source>Jog refused: emergency stop is active</source>
            <translation>Tippbetrieb abgelehnt: Not-Aus ist aktiv</translation>
        </message>
        <message>
            <source>Jog refused: no machine</source>
            <translation>Tippbetrieb abgelehnt: keine Maschine</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::JogPanel</name>
        <message>
            <source>Drag the knob to jog X and Y; speed follows the deflection. Release to stop (ramped).</source>
            <translation>Knopf ziehen, um X und Y zu verfahren; die Geschwindigkeit folgt der Auslenkung. Loslassen stoppt (mit Rampe).</translation>
        </message>
        <message>
            <source>Drag to jog Z; release to stop (ramped).</source>
            <translation>Ziehen, um Z zu verfahren; Loslassen stoppt (mit Rampe).</translation>
        </message>
        <message>
            <source>Speed override</source>
            <translation>Geschwindigkeits-Override</translation>
        </message>
        <message>
            <source>Scales every jog speed (pad, keyboard, gamepad)</source>
            <translation>Skaliert jede Tippgeschwindigkeit (Pad, Tastatur, Gamepad)</translation>
        </message>
        <message>
            <source>Keyboard jog</source>
            <translation>Tastatur-Tippbetrieb</translation>
        </message>
        <message>
            <source>Jog settings</source>
            <translation>Tipp-Einstellungen</translation>
        </message>
        <message>
            <source>Jog settings…</source>
            <translation>Tipp-Einstellungen…</translation>
        </message>
        <message>
            <source>Max jog speed per axis, dead zone, response curve, keyboard speed</source>
            <translation>Maximale Tippgeschwindigkeit je Achse, Totzone, Kennlinie, Tastaturgeschwindigkeit</translation>
        </message>
        <message>
            <source>Keyboard jog: off (Ctrl+J)</source>
            <translation>Tastatur-Tippbetrieb: aus (Strg+J)</translation>
        </message>
        <message>
            <source>Keyboard jog: on, but not connected</source>
            <translation>Tastatur-Tippbetrieb: ein, aber nicht verbunden</translation>
        </message>
        <message>
            <source>Keyboard jog paused: the StepDeck window is not active</source>
            <translation>Tastatur-Tippbetrieb pausiert: das StepDeck-Fenster ist nicht aktiv</translation>
        </message>
        <message>
            <source>Keyboard jog paused: a text field has the focus, the arrows edit it. Click the jog panel to resume.</source>
            <translation>Tastatur-Tippbetrieb pausiert: ein Textfeld hat den Fokus, die Pfeile bearbeiten es. Zum Fortsetzen auf das Tipp-Feld klicken.</translation>
        </message>
        <message>
            <source>Keyboard jog ON: %1</source>
            <translation>Tastatur-Tippbetrieb EIN: %1</translation>
        </message>
        <message>
            <source>Arrows jog X/Y, Page Up/Down jog Z while this window is active and no text field has the focus (Ctrl+J)</source>
            <translation>Pfeile tippen X/Y, Bild auf/ab tippen Z, solange dieses Fenster aktiv ist und kein Textfeld den Fokus hat (Strg+J)</translation>
        </message>
        <message>
            <source>This controller has no jog command: the pad, keys and gamepad move it by short targets, each sent only after the previous one arrived. Releasing ends jogging after the short move under way. Incremental jog moves by the step size.</source>
            <translation>Diese Steuerung hat keinen Tippbefehl: Joystick, Tasten und Gamepad fahren sie in kurzen Zielen, jedes erst nachdem das vorige erreicht ist. Loslassen beendet den Tippbetrieb nach der laufenden kurzen Fahrt. Schrittweises Tippen fährt um die Schrittweite.</translation>
        </message>
        <message>
            <source>The machine axis this stick and End/Home jog</source>
            <translation>Die Maschinenachse, die dieser Stick und Ende/Pos1 verfahren</translation>
        </message>
        <message>
            <source>Drag to jog %1; release to stop (ramped).</source>
            <translation>Ziehen, um %1 zu verfahren; Loslassen stoppt (mit Rampe).</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::JogSettingsWidget</name>
        <message>
            <source>Jog settings</source>
            <translation>Tipp-Einstellungen</translation>
        </message>
        <message>
            <source>Deflection of the pad that gives no motion</source>
            <translation>Auslenkung des Pads, die keine Bewegung erzeugt</translation>
        </message>
        <message>
            <source>Linear</source>
            <translation>Linear</translation>
        </message>
        <message>
            <source>Quadratic (fine near centre)</source>
            <translation>Quadratisch (fein nahe der Mitte)</translation>
        </message>
        <message>
            <source>Cubic (finest near centre)</source>
            <translation>Kubisch (am feinsten nahe der Mitte)</translation>
        </message>
        <message>
            <source>Keyboard jog speed as a share of the max jog speed</source>
            <translation>Tastatur-Tippgeschwindigkeit als Anteil der maximalen Tippgeschwindigkeit</translation>
        </message>
        <message>
            <source>Dead zone:</source>
            <translation>Totzone:</translation>
        </message>
        <message>
            <source>Response:</source>
            <translation>Kennlinie:</translation>
        </message>
        <message>
            <source>Keyboard speed:</source>
            <translation>Tastaturgeschwindigkeit:</translation>
        </message>
        <message>
            <source>Jog speed of axis %1 at full deflection and 100 % override</source>
            <translation>Tippgeschwindigkeit der Achse %1 bei voller Auslenkung und 100 % Override</translation>
        </message>
        <message>
            <source>Max %1:</source>
            <translation>Max. %1:</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::JogStopDistanceLabel</name>
        <message>
            <source>How far each axis still travels after the pad, key or gamepad is let go at the jog speed set now (max speed x override)</source>
            <translation>Wie weit jede Achse noch fährt, nachdem Pad, Taste oder Gamepad bei der jetzt eingestellten Tippgeschwindigkeit losgelassen wurde (Maximalgeschwindigkeit x Override)</translation>
        </message>
        <message>
            <source>%1 %2 mm</source>
            <translation>%1 %2 mm</translation>
        </message>
        <message>
            <source>%1 %2 deg</source>
            <translation>%1 %2°</translation>
        </message>
        <message>
            <source>%1 %2 steps</source>
            <translation>%1 %2 Schritte</translation>
        </message>
        <message>
            <source>Stops by the controller's own ramp after a release</source>
            <translation>Hält nach dem Loslassen mit der eigenen Rampe der Steuerung an</translation>
        </message>
        <message>
            <source>Stops within %1</source>
            <translation>Anhalteweg: %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::JogVelocityReadout</name>
        <message>
            <source>Commanded jog velocity</source>
            <translation>Soll-Tippgeschwindigkeit</translation>
        </message>
        <message>
            <source>%1/s</source>
            <translation>%1/s</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::JoystickPad</name>
        <message>
            <source>LIMIT</source>
            <translation>ENDSCHALTER</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::KeyboardJog</name>
        <message>
            <source>Keyboard</source>
            <translation>Tastatur</translation>
        </message>
        <message>
            <source>←/→ %1</source>
            <translation>←/→ %1</translation>
        </message>
        <message>
            <source>↓/↑ %1</source>
            <translation>↓/↑ %1</translation>
        </message>
        <message>
            <source>Page Down/Up %1</source>
            <translation>Bild ab/auf %1</translation>
        </message>
        <message>
            <source>End/Home %1</source>
            <translation>Ende/Pos1 %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::LaserBridgePage</name>
        <message>
            <source>Start bridge</source>
            <translation>Brücke starten</translation>
        </message>
        <message>
            <source>Stop bridge</source>
            <translation>Brücke anhalten</translation>
        </message>
        <message>
            <source>Laser axis</source>
            <translation>Laserachse</translation>
        </message>
        <message>
            <source>Axis</source>
            <translation>Achse</translation>
        </message>
        <message>
            <source>State</source>
            <translation>Zustand</translation>
        </message>
        <message>
            <source>Target</source>
            <translation>Ziel</translation>
        </message>
        <message>
            <source>Referenced</source>
            <translation>Referenziert</translation>
        </message>
        <message>
            <source>Last answer</source>
            <translation>Letzte Antwort</translation>
        </message>
        <message>
            <source>Laser frames and answers:</source>
            <translation>Rahmen des Lasers und Antworten:</translation>
        </message>
        <message>
            <source>Not running.</source>
            <translation>Läuft nicht.</translation>
        </message>
        <message>
            <source>StepDeck answers the laser marker's motor-axis frames (RS232, 9600 8N1) with the connected controller.</source>
            <translation>StepDeck beantwortet die Motorachsen-Rahmen des Markierlasers (RS232, 9600 8N1) mit der verbundenen Steuerung.</translation>
        </message>
        <message>
            <source>The serial port cabled to the laser's XYZ-control port</source>
            <translation>Die serielle Schnittstelle, die mit dem XYZ-Steuerport des Lasers verbunden ist</translation>
        </message>
        <message>
            <source>Laser port:</source>
            <translation>Laser-Port:</translation>
        </message>
        <message>
            <source>Controller steps per laser position unit: a target goes to target x scale steps from the reference</source>
            <translation>Schritte der Steuerung pro Positionseinheit des Lasers: ein Ziel wird zu Ziel x Maßstab Schritten ab der Referenz</translation>
        </message>
        <message>
            <source>Steps per laser unit:</source>
            <translation>Schritte pro Lasereinheit:</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keiner</translation>
        </message>
        <message>
            <source>A controller input wired to the door switch (set = door open), where the controller publishes its inputs</source>
            <translation>Ein Eingang der Steuerung, an dem der Türschalter hängt (gesetzt = Tür offen), wo die Steuerung ihre Eingänge meldet</translation>
        </message>
        <message>
            <source>Door switch input:</source>
            <translation>Eingang Türschalter:</translation>
        </message>
        <message>
            <source>Controller axis</source>
            <translation>Steuerungsachse</translation>
        </message>
        <message>
            <source>Reference direction</source>
            <translation>Referenzrichtung</translation>
        </message>
        <message>
            <source>negative (-1)</source>
            <translation>negativ (-1)</translation>
        </message>
        <message>
            <source>positive (+1)</source>
            <translation>positiv (+1)</translation>
        </message>
        <message>
            <source>%1 (%2)</source>
            <translation>%1 (%2)</translation>
        </message>
        <message>
            <source>STOP, PANIC and jog keep priority over the bridge: a target the operator stopped is not answered (the laser raises its timeout alarm), and targets that arrive while the operator jogs are dropped.</source>
            <translation>STOPP, PANIK und Tippbetrieb haben Vorrang vor der Brücke: ein Ziel, das der Bediener gestoppt hat, wird nicht beantwortet (der Laser meldet seinen Zeitüberschreitungsalarm), und Ziele, die während des Tippbetriebs ankommen, werden verworfen.</translation>
        </message>
        <message>
            <source>not used</source>
            <translation>nicht benutzt</translation>
        </message>
        <message>
            <source>Connect the controller first.</source>
            <translation>Zuerst die Steuerung verbinden.</translation>
        </message>
        <message>
            <source>Choose the laser's port.</source>
            <translation>Den Port des Lasers wählen.</translation>
        </message>
        <message>
            <source>The laser's port is the controller's port.</source>
            <translation>Der Port des Lasers ist der Port der Steuerung.</translation>
        </message>
        <message>
            <source>This controller publishes no inputs: no door switch input.</source>
            <translation>Diese Steuerung meldet keine Eingänge: kein Türschalter-Eingang möglich.</translation>
        </message>
        <message>
            <source>Running: answering the laser on %1.</source>
            <translation>Läuft: beantwortet den Laser an %1.</translation>
        </message>
        <message>
            <source>Laser bridge failed: %1</source>
            <translation>Laserbrücke fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>Opening %1…</source>
            <translation>Öffne %1…</translation>
        </message>
        <message>
            <source>Stopping…</source>
            <translation>Halte an…</translation>
        </message>
        <message>
            <source>yes</source>
            <translation>ja</translation>
        </message>
        <message>
            <source>no</source>
            <translation>nein</translation>
        </message>
        <message>
            <source>chosen by the controller</source>
            <translation>von der Steuerung gewählt</translation>
        </message>
        <message>
            <source>The controller chooses the direction of its reference run itself</source>
            <translation>Die Steuerung wählt die Richtung ihrer Referenzfahrt selbst</translation>
        </message>
        <message>
            <source>At %1: %2</source>
            <translation>Um %1: %2</translation>
        </message>
        <message>
            <source>Laser port and axes</source>
            <translation>Laser-Port und Achsen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineBar</name>
        <message>
            <source>Pages show:</source>
            <translation>Seiten zeigen:</translation>
        </message>
        <message>
            <source>The controller whose setup, records, traffic, drives and charts the pages show</source>
            <translation>Die Steuerung, deren Einrichtung, Sätze, Verkehr, Antriebe und Diagramme die Seiten zeigen</translation>
        </message>
        <message>
            <source>Connect or disconnect every controller of the machine</source>
            <translation>Alle Steuerungen der Maschine verbinden oder trennen</translation>
        </message>
        <message>
            <source>Machine:</source>
            <translation>Maschine:</translation>
        </message>
        <message>
            <source>simulator</source>
            <translation>Simulator</translation>
        </message>
        <message>
            <source>%1 @ %2</source>
            <translation>%1 @ %2</translation>
        </message>
        <message>
            <source>Disconnected</source>
            <translation>Getrennt</translation>
        </message>
        <message>
            <source>Connecting</source>
            <translation>Verbinde</translation>
        </message>
        <message>
            <source>Connected</source>
            <translation>Verbunden</translation>
        </message>
        <message>
            <source>Link lost</source>
            <translation>Verbindung verloren</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>%1: %2 (%3)</source>
            <translation>%1: %2 (%3)</translation>
        </message>
        <message>
            <source>Disconnect all</source>
            <translation>Alle trennen</translation>
        </message>
        <message>
            <source>Connect all</source>
            <translation>Alle verbinden</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineContext</name>
        <message>
            <source>A machine is open: close it to connect a single controller.</source>
            <translation>Eine Maschine ist geöffnet: Schließen Sie sie, um eine einzelne Steuerung zu verbinden.</translation>
        </message>
        <message>
            <source>Machine file %1: %2</source>
            <translation>Maschinendatei %1: %2</translation>
        </message>
        <message>
            <source>Machine "%1": %2</source>
            <translation>Maschine "%1": %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineControl</name>
        <message>
            <source>Machine "%1" opened: %2 controllers, %3 axes.</source>
            <translation>Maschine "%1" geöffnet: %2 Steuerungen, %3 Achsen.</translation>
        </message>
        <message>
            <source>%1 cannot be stopped from here: %2</source>
            <translation>%1 kann von hier nicht gestoppt werden: %2</translation>
        </message>
        <message>
            <source>Stop: no controller is connected</source>
            <translation>Stopp: Keine Steuerung ist verbunden</translation>
        </message>
        <message>
            <source>Panic: no controller is connected</source>
            <translation>Panik-Stopp: keine Steuerung ist verbunden</translation>
        </message>
        <message>
            <source>PANIC STOP sent to %1: positions are lost, reference all axes before moving.</source>
            <translation>PANIK-STOPP an %1 gesendet: die Positionen sind verloren, vor dem Verfahren alle Achsen referenzieren.</translation>
        </message>
        <message>
            <source>Stop sent to %1: waiting for standstill…</source>
            <translation>Stopp an %1 gesendet: warte auf Stillstand…</translation>
        </message>
        <message>
            <source>PANIC STOP: %1 confirmed standstill; positions are lost, reference all axes before moving.</source>
            <translation>PANIK-STOPP: %1 hat den Stillstand bestätigt; die Positionen sind verloren, vor dem Verfahren alle Achsen referenzieren.</translation>
        </message>
        <message>
            <source>Stopped: every controller confirmed standstill (%1).</source>
            <translation>Gestoppt: jede Steuerung hat den Stillstand bestätigt (%1).</translation>
        </message>
        <message>
            <source>Stopped: %1 confirmed standstill.</source>
            <translation>Gestoppt: %1 hat den Stillstand bestätigt.</translation>
        </message>
        <message>
            <source>PANIC STOP not confirmed by "%1": %2</source>
            <translation>PANIK-STOPP nicht bestätigt von „%1“: %2</translation>
        </message>
        <message>
            <source>STOP not confirmed by "%1": %2</source>
            <translation>STOPP nicht bestätigt von „%1“: %2</translation>
        </message>
        <message>
            <source>PANIC STOP: %1 confirmed standstill since; positions are lost, reference all axes before moving.</source>
            <translation>PANIK-STOPP: %1 hat inzwischen den Stillstand bestätigt; Positionen sind verloren, vor dem Verfahren alle Achsen referenzieren.</translation>
        </message>
        <message>
            <source>STOP: %1 confirmed standstill since.</source>
            <translation>STOPP: %1 hat inzwischen den Stillstand bestätigt.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineDro</name>
        <message>
            <source>mm</source>
            <translation>mm</translation>
        </message>
        <message>
            <source>deg</source>
            <translation>°</translation>
        </message>
        <message>
            <source>steps</source>
            <translation>Schritte</translation>
        </message>
        <message>
            <source>NO LINK</source>
            <translation>KEINE VERBINDUNG</translation>
        </message>
        <message>
            <source>MOVING</source>
            <translation>FÄHRT</translation>
        </message>
        <message>
            <source>UNKNOWN</source>
            <translation>UNBEKANNT</translation>
        </message>
        <message>
            <source>ESTIMATED</source>
            <translation>GESCHÄTZT</translation>
        </message>
        <message>
            <source>REFERENCED</source>
            <translation>REFERENZIERT</translation>
        </message>
        <message>
            <source>Controller "%1" is not connected: this is the last value known, not the position now.</source>
            <translation>Steuerung "%1" ist nicht verbunden: Das ist der letzte bekannte Wert, nicht die Position jetzt.</translation>
        </message>
        <message>
            <source>Not referenced since the last panic, reset or reconnect: the position is counted from where the axis was, not from the machine origin.</source>
            <translation>Seit dem letzten Panik-Stopp, Reset oder Neuverbinden nicht referenziert: die Position zählt ab dem Ort, an dem die Achse stand, nicht ab dem Maschinen-Nullpunkt.</translation>
        </message>
        <message>
            <source>Moving, as the controller reports.</source>
            <translation>Fährt, wie die Steuerung meldet.</translation>
        </message>
        <message>
            <source>Estimated by the host; the controller did not confirm it.</source>
            <translation>Vom Rechner geschätzt; die Steuerung hat es nicht bestätigt.</translation>
        </message>
        <message>
            <source>Known from the controller: read back or set by a reference run.</source>
            <translation>Von der Steuerung bekannt: zurückgelesen oder durch eine Referenzfahrt gesetzt.</translation>
        </message>
        <message>
            <source>Clear work offsets</source>
            <translation>Werkstück-Nullpunkte löschen</translation>
        </message>
        <message>
            <source>Show machine positions again (work origin = machine origin)</source>
            <translation>Wieder Maschinenpositionen anzeigen (Werkstück-Nullpunkt = Maschinen-Nullpunkt)</translation>
        </message>
        <message>
            <source>Zero %1</source>
            <translation>%1 nullen</translation>
        </message>
        <message>
            <source>Set the work origin of %1 at the current position</source>
            <translation>Werkstück-Nullpunkt von %1 auf die aktuelle Position setzen</translation>
        </message>
        <message>
            <source>%1 work</source>
            <translation>%1 Werkstück</translation>
        </message>
        <message>
            <source>Work position: the machine position minus the work zero of %1 (machine %2 %3)</source>
            <translation>Werkstückposition: die Maschinenposition minus den Werkstück-Nullpunkt von %1 (Maschine %2 %3)</translation>
        </message>
        <message>
            <source>Machine position (no work zero set for %1)</source>
            <translation>Maschinenposition (kein Werkstück-Nullpunkt für %1 gesetzt)</translation>
        </message>
        <message>
            <source>Work origin of %1 set at machine %2 %3.</source>
            <translation>Werkstück-Nullpunkt von %1 auf Maschine %2 %3 gesetzt.</translation>
        </message>
        <message>
            <source>Work offsets cleared: machine positions are shown.</source>
            <translation>Werkstück-Nullpunkte gelöscht: Maschinenpositionen werden angezeigt.</translation>
        </message>
        <message>
            <source>moving to %1 %2 (machine %3 %4)</source>
            <translation>fährt nach %1 %2 (Maschine %3 %4)</translation>
        </message>
        <message>
            <source>Estimated from the ramp parameters; the controller reports no position during a move. The target is shown below.</source>
            <translation>Aus den Rampenparametern geschätzt; die Steuerung meldet während einer Fahrt keine Position. Das Ziel steht darunter.</translation>
        </message>
        <message>
            <source>The controller reports no position during a move and the ramp parameters are not known in this session: the target is shown (→), not where the axis is now.</source>
            <translation>Die Steuerung meldet während einer Fahrt keine Position, und die Rampenparameter sind in dieser Sitzung nicht bekannt: angezeigt wird das Ziel (→), nicht wo die Achse jetzt ist.</translation>
        </message>
        <message>
            <source>machine %1 %2 (%3 %4)</source>
            <translation>Maschine %1 %2 (%3 %4)</translation>
        </message>
        <message>
            <source>machine %1 %2, %3 axis %4: %5 %6</source>
            <translation>Maschine %1 %2, %3 Achse %4: %5 %6</translation>
        </message>
        <message>
            <source>The coordinate system shown, zeroed by Zero, used by Go to and by programs without G54..G59</source>
            <translation>Das angezeigte Koordinatensystem: „nullen“ setzt es, Anfahren und Programme ohne G54..G59 verwenden es</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineEditor</name>
        <message>
            <source>New machine</source>
            <translation>Neue Maschine</translation>
        </message>
        <message>
            <source>Add controller</source>
            <translation>Steuerung hinzufügen</translation>
        </message>
        <message>
            <source>Remove controller</source>
            <translation>Steuerung entfernen</translation>
        </message>
        <message>
            <source>Add axis</source>
            <translation>Achse hinzufügen</translation>
        </message>
        <message>
            <source>Remove axis</source>
            <translation>Achse entfernen</translation>
        </message>
        <message>
            <source>Machine name</source>
            <translation>Maschinenname</translation>
        </message>
        <message>
            <source>Controllers</source>
            <translation>Steuerungen</translation>
        </message>
        <message>
            <source>Axes</source>
            <translation>Achsen</translation>
        </message>
        <message>
            <source>Open…</source>
            <translation>Öffnen…</translation>
        </message>
        <message>
            <source>Save</source>
            <translation>Speichern</translation>
        </message>
        <message>
            <source>Save as…</source>
            <translation>Speichern unter…</translation>
        </message>
        <message>
            <source>Close</source>
            <translation>Schließen</translation>
        </message>
        <message>
            <source>Valid machine with the axes %1</source>
            <translation>Gültige Maschine mit den Achsen %1</translation>
        </message>
        <message>
            <source>Machine editor – %1[*]</source>
            <translation>Maschineneditor – %1[*]</translation>
        </message>
        <message>
            <source>unnamed</source>
            <translation>unbenannt</translation>
        </message>
        <message>
            <source>StepDeck machines (*.machine.json);;JSON files (*.json)</source>
            <translation>StepDeck-Maschinen (*.machine.json);;JSON-Dateien (*.json)</translation>
        </message>
        <message>
            <source>Not opened: %1: %2</source>
            <translation>Nicht geöffnet: %1: %2</translation>
        </message>
        <message>
            <source>Not saved: %1</source>
            <translation>Nicht gespeichert: %1</translation>
        </message>
        <message>
            <source>Saved to %1</source>
            <translation>Gespeichert in %1</translation>
        </message>
        <message>
            <source>Save machine</source>
            <translation>Maschine speichern</translation>
        </message>
        <message>
            <source>Open machine</source>
            <translation>Maschine öffnen</translation>
        </message>
        <message>
            <source>Unsaved changes</source>
            <translation>Ungespeicherte Änderungen</translation>
        </message>
        <message>
            <source>The machine "%1" has unsaved changes. Save them?</source>
            <translation>Die Maschine "%1" hat ungespeicherte Änderungen. Speichern?</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keine</translation>
        </message>
        <message>
            <source>The spindle speed in rpm that the controller's full spindle range stands for: a program's S is then in rpm (S12000 of 24000 is half the range). Empty: S is sent in the controller's own units.</source>
            <translation>Die Spindeldrehzahl in U/min, für die der volle Spindelbereich der Steuerung steht: S eines Programms ist dann in U/min (S12000 von 24000 ist der halbe Bereich). Leer: S wird in den eigenen Einheiten der Steuerung gesendet.</translation>
        </message>
        <message>
            <source>Spindle max rpm</source>
            <translation>Spindel max. U/min</translation>
        </message>
        <message>
            <source>Feed across controllers</source>
            <translation>Vorschub über Steuerungen hinweg</translation>
        </message>
        <message>
            <source>Allow feed moves (G1, G2, G3) whose axes sit on several controllers. They start together but share no clock, so their path is only approximate; off, the program check refuses them.</source>
            <translation>Vorschubbewegungen (G1, G2, G3) erlauben, deren Achsen an mehreren Steuerungen hängen. Sie starten gemeinsam, haben aber keinen gemeinsamen Takt, daher ist ihre Bahn nur ungefähr; aus: die Programmprüfung lehnt sie ab.</translation>
        </message>
        <message>
            <source>Re-open machine</source>
            <translation>Maschine neu öffnen</translation>
        </message>
        <message>
            <source>Close the machine the window runs and open it again from the saved file. Its positions are unknown until the axes are referenced again, as after any reconnect.</source>
            <translation>Die Maschine, mit der das Fenster arbeitet, schließen und aus der gespeicherten Datei neu öffnen. Ihre Positionen sind unbekannt, bis die Achsen erneut referenziert sind, wie nach jedem Neuverbinden.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineFileActions</name>
        <message>
            <source>&amp;New machine…</source>
            <translation>&amp;Neue Maschine…</translation>
        </message>
        <message>
            <source>&amp;Open machine…</source>
            <translation>Maschine ö&amp;ffnen…</translation>
        </message>
        <message>
            <source>&amp;Edit machine…</source>
            <translation>Maschine b&amp;earbeiten…</translation>
        </message>
        <message>
            <source>&amp;Recent machines</source>
            <translation>&amp;Zuletzt benutzte Maschinen</translation>
        </message>
        <message>
            <source>Edit the machine open now, or choose a machine file to edit</source>
            <translation>Die geöffnete Maschine bearbeiten oder eine Maschinendatei zum Bearbeiten wählen</translation>
        </message>
        <message>
            <source>Open machine</source>
            <translation>Maschine öffnen</translation>
        </message>
        <message>
            <source>StepDeck machines (*.machine.json);;JSON files (*.json)</source>
            <translation>StepDeck-Maschinen (*.machine.json);;JSON-Dateien (*.json)</translation>
        </message>
        <message>
            <source>Edit machine</source>
            <translation>Maschine bearbeiten</translation>
        </message>
        <message>
            <source>No recent machines</source>
            <translation>Keine zuletzt benutzten Maschinen</translation>
        </message>
        <message>
            <source>Clear list</source>
            <translation>Liste leeren</translation>
        </message>
        <message>
            <source>&amp;Tool table…</source>
            <translation>&amp;Werkzeugtabelle…</translation>
        </message>
        <message>
            <source>The machine's tools: the lengths G43 applies, the texts M6 shows</source>
            <translation>Die Werkzeuge der Maschine: die Längen, die G43 anwendet, die Texte, die M6 zeigt</translation>
        </message>
        <message>
            <source>Saved. The open machine "%1" still runs on the description it was opened with: re-open it to use the saved file.</source>
            <translation>Gespeichert. Die geöffnete Maschine „%1“ läuft weiter mit der Beschreibung, mit der sie geöffnet wurde: Öffnen Sie sie neu, um die gespeicherte Datei zu verwenden.</translation>
        </message>
        <message>
            <source>not possible here</source>
            <translation>hier nicht möglich</translation>
        </message>
        <message>
            <source>Machine re-opened from the saved file: its positions are unknown until the axes are referenced again.</source>
            <translation>Maschine aus der gespeicherten Datei neu geöffnet: Ihre Positionen sind unbekannt, bis die Achsen erneut referenziert sind.</translation>
        </message>
        <message>
            <source>Not re-opened: %1</source>
            <translation>Nicht neu geöffnet: %1</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineGoTo</name>
        <message>
            <source>Go to</source>
            <translation>Anfahren</translation>
        </message>
        <message>
            <source>Go to:</source>
            <translation>Anfahren:</translation>
        </message>
        <message>
            <source>Go-to refused: %1</source>
            <translation>Anfahren abgelehnt: %1</translation>
        </message>
        <message>
            <source>Go-to failed: %1</source>
            <translation>Anfahren fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>Go to (work):</source>
            <translation>Anfahren (Werkstück):</translation>
        </message>
        <message>
            <source>Go-to refused: the last go-to is still moving.</source>
            <translation>Anfahren abgelehnt: die letzte Anfahrt läuft noch.</translation>
        </message>
        <message>
            <source>%1 stands: reading its position…</source>
            <translation>%1 steht: Position wird gelesen…</translation>
        </message>
        <message>
            <source>%1 stands; its position could not be read.</source>
            <translation>%1 steht; die Position konnte nicht gelesen werden.</translation>
        </message>
        <message>
            <source>The checked axes go together, in one rapid move (G0)</source>
            <translation>Die angehakten Achsen fahren gemeinsam, in einer Eilgangbewegung (G0)</translation>
        </message>
        <message>
            <source>Axis %1 goes with the others checked</source>
            <translation>Achse %1 fährt mit den anderen angehakten</translation>
        </message>
        <message>
            <source>Target of %1 in work coordinates (its work zero is subtracted from machine positions); the axis must be referenced</source>
            <translation>Ziel von %1 in Werkstückkoordinaten (ihr Werkstücknullpunkt wird von den Maschinenpositionen abgezogen); die Achse muss referenziert sein</translation>
        </message>
        <message>
            <source>Absolute target of %1 in its unit; the axis must be referenced</source>
            <translation>Absolutes Ziel von %1 in ihrer Einheit; die Achse muss referenziert sein</translation>
        </message>
        <message>
            <source>%1 to %2 (work; machine %3)</source>
            <translation>%1 nach %2 (Werkstück; Maschine %3)</translation>
        </message>
        <message>
            <source>%1 to %2</source>
            <translation>%1 nach %2</translation>
        </message>
        <message>
            <source>Go-to refused: no axis is checked.</source>
            <translation>Anfahren abgelehnt: keine Achse ist angehakt.</translation>
        </message>
        <message>
            <source>Moving %1…</source>
            <translation>Fahre %1…</translation>
        </message>
        <message>
            <source>Checking the go-to of %1…</source>
            <translation>Prüfe das Anfahren von %1…</translation>
        </message>
        <message>
            <source>%1 stand: reading their positions…</source>
            <translation>%1 stehen: Positionen werden gelesen…</translation>
        </message>
        <message>
            <source>%1 stand; their positions could not be read.</source>
            <translation>%1 stehen; die Positionen konnten nicht gelesen werden.</translation>
        </message>
        <message>
            <source>%1 stopped at %2 before its target %3</source>
            <translation>%1 hielt bei %2 vor dem Ziel %3 an</translation>
        </message>
        <message>
            <source>%1 arrived</source>
            <translation>%1 angekommen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineMdi</name>
        <message>
            <source>the machine was closed</source>
            <translation>die Maschine wurde geschlossen</translation>
        </message>
        <message>
            <source>no machine is open</source>
            <translation>keine Maschine ist geöffnet</translation>
        </message>
        <message>
            <source>the last line has not ended</source>
            <translation>die letzte Zeile ist noch nicht beendet</translation>
        </message>
        <message>
            <source>refused</source>
            <translation>abgelehnt</translation>
        </message>
        <message>
            <source>stopped while the line was checked</source>
            <translation>gestoppt, während die Zeile geprüft wurde</translation>
        </message>
        <message>
            <source>an MDI line runs</source>
            <translation>eine MDI-Zeile läuft</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineReferenceRows</name>
        <message>
            <source>Axis</source>
            <translation>Achse</translation>
        </message>
        <message>
            <source>Direction</source>
            <translation>Richtung</translation>
        </message>
        <message>
            <source>Order</source>
            <translation>Reihenfolge</translation>
        </message>
        <message>
            <source>State</source>
            <translation>Zustand</translation>
        </message>
        <message>
            <source>controller chooses</source>
            <translation>Steuerung wählt</translation>
        </message>
        <message>
            <source>+ (positive)</source>
            <translation>+ (positiv)</translation>
        </message>
        <message>
            <source>− (negative)</source>
            <translation>− (negativ)</translation>
        </message>
        <message>
            <source>Reference %1</source>
            <translation>%1 referenzieren</translation>
        </message>
        <message>
            <source>unknown (no link)</source>
            <translation>unbekannt (keine Verbindung)</translation>
        </message>
        <message>
            <source>referencing…</source>
            <translation>referenziere…</translation>
        </message>
        <message>
            <source>referenced</source>
            <translation>referenziert</translation>
        </message>
        <message>
            <source>not referenced</source>
            <translation>nicht referenziert</translation>
        </message>
        <message>
            <source>The machine's referencing: edit it with File → Edit machine…</source>
            <translation>Die Referenzierung der Maschine: zu bearbeiten mit Datei → Maschine bearbeiten…</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MachineStopWatch</name>
        <message>
            <source>no standstill reported within %1 s</source>
            <translation>kein Stillstand innerhalb von %1 s gemeldet</translation>
        </message>
        <message>
            <source>no answer to the stop within %1 s</source>
            <translation>keine Antwort auf den Stopp innerhalb von %1 s</translation>
        </message>
        <message>
            <source>its link was lost</source>
            <translation>die Verbindung ist verloren</translation>
        </message>
        <message>
            <source>the stop request failed</source>
            <translation>der Stopp-Befehl ist fehlgeschlagen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MainWindow</name>
        <message>
            <source>Connection</source>
            <translation>Verbindung</translation>
        </message>
        <message>
            <source>&amp;Stop</source>
            <translation>&amp;Stopp</translation>
        </message>
        <message>
            <source>Ramped stop of all motion (Esc)</source>
            <translation>Stopp aller Bewegungen mit Rampe (Esc)</translation>
        </message>
        <message>
            <source>&amp;Panic stop</source>
            <translation>&amp;Panik-Stopp</translation>
        </message>
        <message>
            <source>Immediate stop without ramp (F1); positions are lost</source>
            <translation>Sofortiger Stopp ohne Rampe (F1); die Positionen gehen verloren</translation>
        </message>
        <message>
            <source>&amp;Reference all</source>
            <translation>Alle &amp;referenzieren</translation>
        </message>
        <message>
            <source>&amp;Connect / Disconnect</source>
            <translation>&amp;Verbinden / Trennen</translation>
        </message>
        <message>
            <source>Reset &amp;controller</source>
            <translation>&amp;Steuerung zurücksetzen</translation>
        </message>
        <message>
            <source>&amp;Keyboard jog</source>
            <translation>&amp;Tastatur-Tippbetrieb</translation>
        </message>
        <message>
            <source>Position</source>
            <translation>Position</translation>
        </message>
        <message>
            <source>Referencing</source>
            <translation>Referenzfahrt</translation>
        </message>
        <message>
            <source>Status</source>
            <translation>Status</translation>
        </message>
        <message>
            <source>Gamepad</source>
            <translation>Gamepad</translation>
        </message>
        <message>
            <source>Setup</source>
            <translation>Einrichtung</translation>
        </message>
        <message>
            <source>Traffic</source>
            <translation>Datenverkehr</translation>
        </message>
        <message>
            <source>Charts</source>
            <translation>Diagramme</translation>
        </message>
        <message>
            <source>&amp;File</source>
            <translation>&amp;Datei</translation>
        </message>
        <message>
            <source>&amp;Load parameters…</source>
            <translation>Parameter &amp;laden…</translation>
        </message>
        <message>
            <source>&amp;Save parameters…</source>
            <translation>Parameter &amp;speichern…</translation>
        </message>
        <message>
            <source>Save &amp;traffic…</source>
            <translation>&amp;Datenverkehr speichern…</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>&amp;Beenden</translation>
        </message>
        <message>
            <source>&amp;Machine</source>
            <translation>&amp;Maschine</translation>
        </message>
        <message>
            <source>Refresh &amp;status</source>
            <translation>&amp;Status aktualisieren</translation>
        </message>
        <message>
            <source>&amp;View</source>
            <translation>&amp;Ansicht</translation>
        </message>
        <message>
            <source>Reset &amp;layout</source>
            <translation>&amp;Layout zurücksetzen</translation>
        </message>
        <message>
            <source>&amp;Language</source>
            <translation>&amp;Sprache</translation>
        </message>
        <message>
            <source>System default</source>
            <translation>Systemvorgabe</translation>
        </message>
        <message>
            <source>Language</source>
            <translation>Sprache</translation>
        </message>
        <message>
            <source>The language changes when StepDeck is started again.</source>
            <translation>Die Sprache ändert sich beim nächsten Start von StepDeck.</translation>
        </message>
        <message>
            <source>simulator</source>
            <translation>Simulator</translation>
        </message>
        <message>
            <source>Referencing stopped.</source>
            <translation>Referenzfahrt gestoppt.</translation>
        </message>
        <message>
            <source>Drives</source>
            <translation>Antriebe</translation>
        </message>
        <message>
            <source>Records</source>
            <translation>Sätze</translation>
        </message>
        <message>
            <source>Input programs</source>
            <translation>Eingangsprogramme</translation>
        </message>
        <message>
            <source>Laser bridge</source>
            <translation>Laserbrücke</translation>
        </message>
        <message>
            <source>Messages</source>
            <translation>Meldungen</translation>
        </message>
        <message>
            <source>Program</source>
            <translation>Programm</translation>
        </message>
        <message>
            <source>Program line %1: %2</source>
            <translation>Programmzeile %1: %2</translation>
        </message>
        <message>
            <source>MDI: %1</source>
            <translation>MDI: %1</translation>
        </message>
        <message>
            <source>the laser bridge runs</source>
            <translation>die Laserbrücke läuft</translation>
        </message>
        <message>
            <source>a reference run is under way</source>
            <translation>eine Referenzfahrt läuft</translation>
        </message>
        <message>
            <source>a stop is still waiting for its confirmation</source>
            <translation>ein Stopp wartet noch auf seine Bestätigung</translation>
        </message>
        <message>
            <source>the machine is moving (%1): stop it first</source>
            <translation>die Maschine bewegt sich (%1): zuerst anhalten</translation>
        </message>
        <message>
            <source>Machine not re-opened: %1</source>
            <translation>Maschine nicht neu geöffnet: %1</translation>
        </message>
        <message>
            <source>the saved file does not open: see the message line</source>
            <translation>die gespeicherte Datei lässt sich nicht öffnen: siehe Meldungszeile</translation>
        </message>
        <message>
            <source>Machine re-opened from %1: positions are unknown until the axes are referenced again.</source>
            <translation>Maschine aus %1 neu geöffnet: Die Positionen sind unbekannt, bis die Achsen erneut referenziert sind.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MdiLine</name>
        <message>
            <source>Run line</source>
            <translation>Zeile ausführen</translation>
        </message>
        <message>
            <source>G-code line, e.g. G0 X10 Y5 (Enter runs it, Up: the last)</source>
            <translation>G-Code-Zeile, z. B. G0 X10 Y5 (Enter führt sie aus, Pfeil hoch: die letzte)</translation>
        </message>
        <message>
            <source>Runs the line on the machine after the same check a program has</source>
            <translation>Führt die Zeile auf der Maschine aus, nach derselben Prüfung wie ein Programm</translation>
        </message>
        <message>
            <source>The modal state the next line starts in (LinuxCNC's active G-codes)</source>
            <translation>Der modale Zustand, in dem die nächste Zeile beginnt (die aktiven G-Codes wie in LinuxCNC)</translation>
        </message>
        <message>
            <source>MDI:</source>
            <translation>MDI:</translation>
        </message>
        <message>
            <source>Holding: Resume goes on.</source>
            <translation>Angehalten: Fortsetzen fährt weiter.</translation>
        </message>
        <message>
            <source>Holding: %1 (Resume goes on)</source>
            <translation>Angehalten: %1 (Fortsetzen fährt weiter)</translation>
        </message>
        <message>
            <source>Running: %1</source>
            <translation>Läuft: %1</translation>
        </message>
        <message>
            <source>Refused: %1</source>
            <translation>Abgelehnt: %1</translation>
        </message>
        <message>
            <source>Checking, then running: %1</source>
            <translation>Wird geprüft, dann ausgeführt: %1</translation>
        </message>
        <message>
            <source>Done: %1</source>
            <translation>Erledigt: %1</translation>
        </message>
        <message>
            <source>Not done: %1 (%2)</source>
            <translation>Nicht ausgeführt: %1 (%2)</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Fortsetzen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MessageLine</name>
        <message>
            <source>Open the message log: every message with its time</source>
            <translation>Meldungsprotokoll öffnen: jede Meldung mit ihrer Uhrzeit</translation>
        </message>
        <message>
            <source>Messages (%1)</source>
            <translation>Meldungen (%1)</translation>
        </message>
        <message>
            <source>Messages</source>
            <translation>Meldungen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::MessageLog</name>
        <message>
            <source>Every message of the status line with its time, the newest at the bottom (the last %1 are kept).</source>
            <translation>Jede Meldung der Statuszeile mit ihrer Uhrzeit, die neueste unten (die letzten %1 bleiben erhalten).</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::PadJogSource</name>
        <message>
            <source>Pad %1</source>
            <translation>Joystick %1</translation>
        </message>
        <message>
            <source>Pad</source>
            <translation>Joystick</translation>
        </message>
        <message>
            <source>Jog ended: the pad moved under the held pointer. Release the button and press again.</source>
            <translation>Tippen beendet: Das Pad hat sich unter dem gehaltenen Zeiger bewegt. Maustaste loslassen und neu drücken.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ParameterField</name>
        <message>
            <source>on</source>
            <translation>ein</translation>
        </message>
        <message>
            <source>%1: a value is required</source>
            <translation>%1: ein Wert ist erforderlich</translation>
        </message>
        <message>
            <source>Allowed: %1 to %2 %3</source>
            <translation>Erlaubt: %1 bis %2 %3</translation>
        </message>
        <message>
            <source>unknown</source>
            <translation>unbekannt</translation>
        </message>
        <message>
            <source>Unknown: the value could not be read. It is written only if you set it.</source>
            <translation>Unbekannt: der Wert konnte nicht gelesen werden. Er wird nur geschrieben, wenn Sie ihn setzen.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::PositionErrorResetButton</name>
        <message>
            <source>Reset position error</source>
            <translation>Positionsfehler zurücksetzen</translation>
        </message>
        <message>
            <source>For the drives selected above: take over the encoder position as the position and clear the position error (manual 5.14)</source>
            <translation>Für die oben gewählten Antriebe: die Encoderposition als Position übernehmen und den Positionsfehler löschen (Handbuch 5.14)</translation>
        </message>
        <message>
            <source>the “Reset position error” button on the Drives page</source>
            <translation>der Schaltfläche „Positionsfehler zurücksetzen“ auf der Seite Antriebe</translation>
        </message>
        <message>
            <source>Position error of axis %1 reset: its position is the encoder's now.</source>
            <translation>Positionsfehler der Achse %1 zurückgesetzt: Ihre Position ist jetzt die des Encoders.</translation>
        </message>
        <message>
            <source>Position error of axis %1 not reset: %2</source>
            <translation>Positionsfehler der Achse %1 nicht zurückgesetzt: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::PositionPanel</name>
        <message>
            <source>Units and limits…</source>
            <translation>Einheiten und Grenzen…</translation>
        </message>
        <message>
            <source>Steps per unit, soft limits and referencing of each axis: the machine editor (a controller of the connection bar is saved as a machine file of its own)</source>
            <translation>Schritte pro Einheit, Software-Endlagen und Referenzierung jeder Achse: der Maschineneditor (eine Steuerung der Verbindungsleiste wird als eigene Maschinendatei gespeichert)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::PreviewProjection</name>
        <message>
            <source>This view needs the axes %1; the machine lacks %2.</source>
            <translation>Diese Ansicht braucht die Achsen %1; der Maschine fehlt %2.</translation>
        </message>
        <message>
            <source>Top (X/Y)</source>
            <translation>Oben (X/Y)</translation>
        </message>
        <message>
            <source>Front (X/Z)</source>
            <translation>Vorne (X/Z)</translation>
        </message>
        <message>
            <source>Side (Y/Z)</source>
            <translation>Seite (Y/Z)</translation>
        </message>
        <message>
            <source>Isometric</source>
            <translation>Isometrisch</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramCheckStatus</name>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
        <message>
            <source>Check</source>
            <translation>Prüfen</translation>
        </message>
        <message>
            <source>Checking: %p %</source>
            <translation>Prüfung: %p %</translation>
        </message>
        <message>
            <source>Check the program against the machine now</source>
            <translation>Das Programm jetzt gegen die Maschine prüfen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramControls</name>
        <message>
            <source>Run</source>
            <translation>Starten</translation>
        </message>
        <message>
            <source>&amp;Pause</source>
            <translation>&amp;Pause</translation>
        </message>
        <message>
            <source>Resume</source>
            <translation>Fortsetzen</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>Schritt</translation>
        </message>
        <message>
            <source>&amp;Abort</source>
            <translation>&amp;Abbrechen</translation>
        </message>
        <message>
            <source>Run from line…</source>
            <translation>Ab Zeile starten…</translation>
        </message>
        <message>
            <source>Check the program against the machine and run it from the start</source>
            <translation>Das Programm gegen die Maschine prüfen und von Anfang an ausführen</translation>
        </message>
        <message>
            <source>Finish the current block, then hold</source>
            <translation>Den laufenden Satz beenden, dann anhalten</translation>
        </message>
        <message>
            <source>Go on with the next block</source>
            <translation>Mit dem nächsten Satz weitermachen</translation>
        </message>
        <message>
            <source>Run one block, then hold</source>
            <translation>Einen Satz ausführen, dann anhalten</translation>
        </message>
        <message>
            <source>Stop every controller; the program ends as aborted</source>
            <translation>Alle Steuerungen stoppen; das Programm endet als abgebrochen</translation>
        </message>
        <message>
            <source>Run from the first block on or after this line, starting where the axes stand now</source>
            <translation>Ab dem ersten Satz in oder nach dieser Zeile ausführen, beginnend dort, wo die Achsen jetzt stehen</translation>
        </message>
        <message>
            <source>line </source>
            <translation>Zeile </translation>
        </message>
        <message>
            <source>line %1 of %2</source>
            <translation>Zeile %1 von %2</translation>
        </message>
        <message>
            <source>time left unknown</source>
            <translation>Restzeit unbekannt</translation>
        </message>
        <message>
            <source>not running</source>
            <translation>läuft nicht</translation>
        </message>
        <message>
            <source>Optional stops (M1)</source>
            <translation>Optionaler Halt (M1)</translation>
        </message>
        <message>
            <source>On: the program holds at M1 like at M0 (LinuxCNC's optional stop). Off: it runs past every M1. Counts when the run reaches the M1.</source>
            <translation>Ein: das Programm hält bei M1 wie bei M0 (optionaler Halt wie in LinuxCNC). Aus: es läuft an jedem M1 vorbei. Gilt, wenn der Lauf das M1 erreicht.</translation>
        </message>
        <message>
            <source>Hold</source>
            <translation>Halt</translation>
        </message>
        <message>
            <source> %</source>
            <translation> %</translation>
        </message>
        <message>
            <source>Feed override: a contour runs at this share of F, from its next ticks on (each move at most as fast as one step per tick allows); a block of its own runs at its F</source>
            <translation>Vorschub-Override: Eine Kontur läuft ab ihren nächsten Takten mit diesem Anteil von F (jede Bewegung höchstens so schnell, wie ein Schritt je Takt erlaubt); ein einzelner Satz läuft mit seinem F</translation>
        </message>
        <message>
            <source>Feed hold: stop on the path where the tool is (a contour); a block of its own finishes first. Resume goes on from there. Key: F2</source>
            <translation>Vorschub-Halt: auf der Bahn anhalten, wo das Werkzeug ist (eine Kontur); ein einzelner Satz wird erst zu Ende gefahren. Fortsetzen fährt von dort weiter. Taste: F2</translation>
        </message>
        <message>
            <source>F </source>
            <translation>F </translation>
        </message>
        <message>
            <source>Block delete (/)</source>
            <translation>Satz ausblenden (/)</translation>
        </message>
        <message>
            <source>On: lines starting with "/" are skipped (LinuxCNC's block delete, on as LinuxCNC starts). Off: they run without the "/". The program is checked again when it changes; a run keeps what its check read.</source>
            <translation>Ein: Zeilen, die mit "/" beginnen, werden übersprungen (Satz ausblenden wie in LinuxCNC, eingeschaltet wie beim Start von LinuxCNC). Aus: sie laufen ohne das "/". Das Programm wird bei einer Änderung neu geprüft; ein Lauf behält, was seine Prüfung las.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramErrorList</name>
        <message>
            <source>line %1: %2</source>
            <translation>Zeile %1: %2</translation>
        </message>
        <message>
            <source>No errors.</source>
            <translation>Keine Fehler.</translation>
        </message>
        <message numerus="yes">
            <source>%n error(s); click one to go to its line.</source>
            <translation>
                <numerusform>%n Fehler; ein Klick springt zu seiner Zeile.</numerusform>
                <numerusform>%n Fehler; ein Klick springt zur Zeile des Fehlers.</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Line %1 is not in the editor, which shows the first %n line(s) of this large file.</source>
            <translation>
                <numerusform>Zeile %1 steht nicht im Editor, der von dieser großen Datei nur die erste Zeile zeigt.</numerusform>
                <numerusform>Zeile %1 steht nicht im Editor, der von dieser großen Datei nur die ersten %n Zeilen zeigt.</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramFiles</name>
        <message>
            <source>Motion programs (*.ngc *.nc *.gcode);;All files (*)</source>
            <translation>Bewegungsprogramme (*.ngc *.nc *.gcode);;Alle Dateien (*)</translation>
        </message>
        <message>
            <source>&amp;Open…</source>
            <translation>Ö&amp;ffnen…</translation>
        </message>
        <message>
            <source>&amp;Save</source>
            <translation>&amp;Speichern</translation>
        </message>
        <message>
            <source>Save &amp;as…</source>
            <translation>Speichern &amp;unter…</translation>
        </message>
        <message>
            <source>Recent</source>
            <translation>Zuletzt</translation>
        </message>
        <message>
            <source>Open program</source>
            <translation>Programm öffnen</translation>
        </message>
        <message>
            <source>The program shown has unsaved changes. Discard them and open %1?</source>
            <translation>Das angezeigte Programm hat ungespeicherte Änderungen. Verwerfen und %1 öffnen?</translation>
        </message>
        <message>
            <source>Program %1: cannot be read: %2</source>
            <translation>Programm %1: kann nicht gelesen werden: %2</translation>
        </message>
        <message>
            <source>Program %1: cannot be written: %2</source>
            <translation>Programm %1: kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>Save program</source>
            <translation>Programm speichern</translation>
        </message>
        <message>
            <source>No recent programs</source>
            <translation>Keine zuletzt verwendeten Programme</translation>
        </message>
        <message>
            <source>Untitled</source>
            <translation>Unbenannt</translation>
        </message>
        <message>
            <source>%1 is %2 MB: too large to edit here. Its first %3 lines are shown; the check, the preview and the run read the whole file.</source>
            <translation>%1 ist %2 MB groß: zu groß zum Bearbeiten. Die ersten %3 Zeilen werden gezeigt; Prüfung, Vorschau und Lauf lesen die ganze Datei.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramMachinePositions</name>
        <message>
            <source>%1 unknown</source>
            <translation>%1 unbekannt</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramPage</name>
        <message>
            <source>Aborted: the machine was closed.</source>
            <translation>Abgebrochen: die Maschine wurde geschlossen.</translation>
        </message>
        <message>
            <source>Runs on %1 (axes %2)</source>
            <translation>Läuft auf %1 (Achsen %2)</translation>
        </message>
        <message>
            <source>Not checked: no machine open.</source>
            <translation>Nicht geprüft: keine Maschine geöffnet.</translation>
        </message>
        <message>
            <source>The preview needs a machine: its axes and soft limits.</source>
            <translation>Die Vorschau braucht eine Maschine: ihre Achsen und Software-Endlagen.</translation>
        </message>
        <message>
            <source>Checked against the machine: no errors.</source>
            <translation>Gegen die Maschine geprüft: keine Fehler.</translation>
        </message>
        <message>
            <source>No program.</source>
            <translation>Kein Programm.</translation>
        </message>
        <message numerus="yes">
            <source>%n error(s); line %1: %2</source>
            <translation>
                <numerusform>%n Fehler; Zeile %1: %2</numerusform>
                <numerusform>%n Fehler; Zeile %1: %2</numerusform>
            </translation>
        </message>
        <message>
            <source>No preview: the program has errors.</source>
            <translation>Keine Vorschau: das Programm hat Fehler.</translation>
        </message>
        <message>
            <source>Line %1: no block runs on or after it.</source>
            <translation>Zeile %1: in oder nach ihr läuft kein Satz.</translation>
        </message>
        <message>
            <source>Run from line %1 (%2). The lines before it do not run; the axes start from where they stand now: %3.</source>
            <translation>Ab Zeile %1 starten (%2). Die Zeilen davor laufen nicht; die Achsen beginnen dort, wo sie jetzt stehen: %3.</translation>
        </message>
        <message>
            <source>Run from line</source>
            <translation>Ab Zeile starten</translation>
        </message>
        <message>
            <source>Not started.</source>
            <translation>Nicht gestartet.</translation>
        </message>
        <message>
            <source>Not started: %1</source>
            <translation>Nicht gestartet: %1</translation>
        </message>
        <message numerus="yes">
            <source>Finished: %n block(s) run.</source>
            <translation>
                <numerusform>Fertig: %n Satz ausgeführt.</numerusform>
                <numerusform>Fertig: %n Sätze ausgeführt.</numerusform>
            </translation>
        </message>
        <message>
            <source>Failed: %1</source>
            <translation>Fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>Aborted.</source>
            <translation>Abgebrochen.</translation>
        </message>
        <message>
            <source>Aborted: %1</source>
            <translation>Abgebrochen: %1</translation>
        </message>
        <message>
            <source>Pausing: line %1 finishes first, then the program holds.</source>
            <translation>Pause folgt: Zeile %1 wird noch beendet, dann hält das Programm an.</translation>
        </message>
        <message>
            <source>Running line %1.</source>
            <translation>Zeile %1 läuft.</translation>
        </message>
        <message>
            <source>Paused after line %1: Resume or Step goes on.</source>
            <translation>Angehalten nach Zeile %1: Fortsetzen oder Schritt macht weiter.</translation>
        </message>
        <message>
            <source>Aborting: waiting for the axes to stand.</source>
            <translation>Abbruch: warte auf den Stillstand der Achsen.</translation>
        </message>
        <message>
            <source>Aborting: %1</source>
            <translation>Abbruch: %1</translation>
        </message>
        <message>
            <source>Programs run on a machine: choose a model on the connection bar or open a machine file.</source>
            <translation>Programme laufen auf einer Maschine: ein Modell in der Verbindungsleiste wählen oder eine Maschinendatei öffnen.</translation>
        </message>
        <message>
            <source>Not checked: the check was cancelled. Run stays off until it is checked.</source>
            <translation>Nicht geprüft: die Prüfung wurde abgebrochen. Starten bleibt aus, bis es geprüft ist.</translation>
        </message>
        <message>
            <source>No preview: the check was cancelled.</source>
            <translation>Keine Vorschau: die Prüfung wurde abgebrochen.</translation>
        </message>
        <message>
            <source>the program is not checked yet</source>
            <translation>das Programm ist noch nicht geprüft</translation>
        </message>
        <message>
            <source>stopped while the program was checked before the run</source>
            <translation>gestoppt, während das Programm vor dem Lauf geprüft wurde</translation>
        </message>
        <message>
            <source>Checking the program before the run…</source>
            <translation>Das Programm wird vor dem Lauf geprüft…</translation>
        </message>
        <message>
            <source>This program has parameters or O words: its lines run in the order its control flow gives, so it runs from its start</source>
            <translation>Dieses Programm hat Parameter oder O-Worte: Seine Zeilen laufen in der Reihenfolge, die sein Ablauf vorgibt, daher läuft es von seinem Anfang an</translation>
        </message>
        <message>
            <source>The offsets or tools changed while the run holds: Resume checks the rest of the program with them first.</source>
            <translation>Nullpunkte oder Werkzeuge änderten sich während des Halts: Fortsetzen prüft zuerst den Rest des Programms damit.</translation>
        </message>
        <message>
            <source>First, as the lines before it left them: %1.</source>
            <translation>Zuerst, wie die Zeilen davor sie hinterließen: %1.</translation>
        </message>
        <message>
            <source>Feed hold in line %1: the tool stands on its path; Resume goes on from there.</source>
            <translation>Vorschub-Halt in Zeile %1: das Werkzeug steht auf seiner Bahn; Fortsetzen fährt von dort weiter.</translation>
        </message>
        <message numerus="yes">
            <source>Checked against the machine: no errors; %n note(s), line %1: %2</source>
            <translation>
                <numerusform>Gegen die Maschine geprüft: keine Fehler; %n Hinweis, Zeile %1: %2</numerusform>
                <numerusform>Gegen die Maschine geprüft: keine Fehler; %n Hinweise, Zeile %1: %2</numerusform>
            </translation>
        </message>
        <message>
            <source>Moves first, to where the lines before it leave the tool: %1.</source>
            <translation>Fährt zuerst dorthin, wo die Zeilen davor das Werkzeug lassen: %1.</translation>
        </message>
        <message>
            <source>Then moves to where the lines before it leave the tool: %1.</source>
            <translation>Fährt dann dorthin, wo die Zeilen davor das Werkzeug lassen: %1.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramPathView</name>
        <message>
            <source>Fit</source>
            <translation>Einpassen</translation>
        </message>
        <message>
            <source>Fit the path to the view (F)</source>
            <translation>Die Bahn in die Ansicht einpassen (F)</translation>
        </message>
        <message>
            <source>The program reaches no known position of the axes %1.</source>
            <translation>Das Programm erreicht keine bekannte Position der Achsen %1.</translation>
        </message>
        <message>
            <source>How the path is looked at</source>
            <translation>Blickrichtung auf die Bahn</translation>
        </message>
        <message>
            <source>How the path is looked at. Not on this machine:
%1</source>
            <translation>Blickrichtung auf die Bahn. Auf dieser Maschine nicht möglich:
%1</translation>
        </message>
        <message>
            <source>Feed (G1, arcs)</source>
            <translation>Vorschub (G1, Bögen)</translation>
        </message>
        <message>
            <source>Rapid (G0)</source>
            <translation>Eilgang (G0)</translation>
        </message>
        <message>
            <source>Soft limits (machine travel, in work coordinates)</source>
            <translation>Software-Endlagen (Verfahrweg der Maschine, in Werkstückkoordinaten)</translation>
        </message>
        <message>
            <source>Running line</source>
            <translation>Laufende Zeile</translation>
        </message>
        <message>
            <source>Tool</source>
            <translation>Werkzeug</translation>
        </message>
        <message>
            <source>Drag: turn (X, Y and Z) · Shift+drag or the middle button: pan · wheel: zoom about the pointer · F or a double click: fit · + and -: zoom · arrow keys: pan · Ctrl+arrow keys: turn</source>
            <translation>Ziehen: drehen (X, Y und Z) · Umschalt+Ziehen oder mittlere Taste: verschieben · Mausrad: um den Zeiger zoomen · F oder Doppelklick: einpassen · + und -: zoomen · Pfeiltasten: verschieben · Strg+Pfeiltasten: drehen</translation>
        </message>
        <message>
            <source>Orbit</source>
            <translation>Gedreht</translation>
        </message>
        <message>
            <source>Turned with the mouse: drag the drawing to turn it, choose a view above to turn it back</source>
            <translation>Mit der Maus gedreht: die Zeichnung ziehen, um sie zu drehen; oben eine Ansicht wählen, um zurückzudrehen</translation>
        </message>
        <message>
            <source>Turning the path needs the axes X, Y and Z.</source>
            <translation>Zum Drehen der Bahn braucht es die Achsen X, Y und Z.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramPreviewView</name>
        <message>
            <source>Axis</source>
            <translation>Achse</translation>
        </message>
        <message>
            <source>Program from</source>
            <translation>Programm von</translation>
        </message>
        <message>
            <source>Program to</source>
            <translation>Programm bis</translation>
        </message>
        <message>
            <source>Soft limits</source>
            <translation>Software-Endlagen</translation>
        </message>
        <message>
            <source>Axes over time</source>
            <translation>Achsen über der Zeit</translation>
        </message>
        <message>
            <source>Extents</source>
            <translation>Verfahrbereiche</translation>
        </message>
        <message>
            <source>No program checked yet.</source>
            <translation>Noch kein Programm geprüft.</translation>
        </message>
        <message numerus="yes">
            <source>%n line(s)</source>
            <translation>
                <numerusform>%n Zeile</numerusform>
                <numerusform>%n Zeilen</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n block(s) run</source>
            <translation>
                <numerusform>%n Satz wird ausgeführt</numerusform>
                <numerusform>%n Sätze werden ausgeführt</numerusform>
            </translation>
        </message>
        <message>
            <source>s (estimated)</source>
            <translation>s (geschätzt)</translation>
        </message>
        <message>
            <source>now</source>
            <translation>jetzt</translation>
        </message>
        <message>
            <source>No axis besides X and Y moves.</source>
            <translation>Außer X und Y fährt keine Achse.</translation>
        </message>
        <message>
            <source>%1 … %2 %3</source>
            <translation>%1 … %2 %3</translation>
        </message>
        <message>
            <source>none</source>
            <translation>keine</translation>
        </message>
        <message>
            <source>%1 0 at machine %2 %3</source>
            <translation>%1 0 bei Maschine %2 %3</translation>
        </message>
        <message>
            <source>Work coordinates = machine coordinates (no work zero set)</source>
            <translation>Werkstückkoordinaten = Maschinenkoordinaten (kein Werkstücknullpunkt gesetzt)</translation>
        </message>
        <message>
            <source>Work coordinates: %1</source>
            <translation>Werkstückkoordinaten: %1</translation>
        </message>
        <message>
            <source>The program's positions, the path and the extents are work coordinates, as the position display shows them; the machine moves to work + offset. Soft limits are shown converted to work coordinates.</source>
            <translation>Die Positionen des Programms, die Bahn und die Ausdehnung sind Werkstückkoordinaten, wie die Positionsanzeige sie zeigt; die Maschine fährt nach Werkstück + Versatz. Software-Endlagen werden in Werkstückkoordinaten umgerechnet gezeigt.</translation>
        </message>
        <message>
            <source>Path</source>
            <translation>Bahn</translation>
        </message>
        <message>
            <source>This machine has no two of the axes X, Y and Z: see the other tabs.</source>
            <translation>Diese Maschine hat keine zwei der Achsen X, Y und Z: siehe die anderen Reiter.</translation>
        </message>
        <message>
            <source>path simplified</source>
            <translation>Pfad vereinfacht</translation>
        </message>
        <message>
            <source>Errors</source>
            <translation>Fehler</translation>
        </message>
        <message>
            <source>Errors (%1)</source>
            <translation>Fehler (%1)</translation>
        </message>
        <message>
            <source>The check's errors: Run stays off until there are none.</source>
            <translation>Die Fehler der Prüfung: Starten bleibt aus, bis keine mehr da sind.</translation>
        </message>
        <message>
            <source>The check found no errors.</source>
            <translation>Die Prüfung hat keine Fehler gefunden.</translation>
        </message>
        <message>
            <source>Beyond the soft limits</source>
            <translation>Jenseits der Software-Endlagen</translation>
        </message>
        <message>
            <source>Has errors, not runnable</source>
            <translation>Hat Fehler, nicht ausführbar</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramPromptBanner</name>
        <message>
            <source>Resume</source>
            <translation>Fortsetzen</translation>
        </message>
        <message>
            <source>Keep Z</source>
            <translation>Z behalten</translation>
        </message>
        <message>
            <source>Go on with the work Z as it is: only when the tool in the spindle is the one Z was set for. Another tool needs its touch-off (Zero Z).</source>
            <translation>Mit dem Werkstück-Nullpunkt von Z weiterfahren, wie er ist: nur wenn das Werkzeug in der Spindel das ist, für das Z gesetzt wurde. Ein anderes Werkzeug muss angetastet werden (Z nullen).</translation>
        </message>
        <message>
            <source>Line %1: the program holds. Resume when ready.</source>
            <translation>Zeile %1: Das Programm hält an. Fortsetzen, wenn bereit.</translation>
        </message>
        <message>
            <source>Line %1: %2</source>
            <translation>Zeile %1: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramStarter</name>
        <message>
            <source>the machine was closed</source>
            <translation>die Maschine wurde geschlossen</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ProgramTimes</name>
        <message>
            <source>%1 s</source>
            <translation>%1 s</translation>
        </message>
        <message>
            <source>%1 min %2 s</source>
            <translation>%1 min %2 s</translation>
        </message>
        <message>
            <source>%1 h %2 min</source>
            <translation>%1 h %2 min</translation>
        </message>
        <message>
            <source>≈ %1 (estimated)</source>
            <translation>≈ %1 (geschätzt)</translation>
        </message>
        <message>
            <source>≈ %1 left (estimated)</source>
            <translation>≈ %1 übrig (geschätzt)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::RawWordView</name>
        <message>
            <source>Raw %1:</source>
            <translation>Rohwert %1:</translation>
        </message>
        <message>
            <source>bit %1</source>
            <translation>Bit %1</translation>
        </message>
        <message>
            <source>Not implemented by the firmware: always off.</source>
            <translation>Von der Firmware nicht implementiert: immer aus.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::RecordDelegate</name>
        <message>
            <source>yes</source>
            <translation>ja</translation>
        </message>
        <message>
            <source>no</source>
            <translation>nein</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::RecordsPage</name>
        <message>
            <source>Drive:</source>
            <translation>Antrieb:</translation>
        </message>
        <message>
            <source>Record:</source>
            <translation>Satz:</translation>
        </message>
        <message>
            <source>Read all</source>
            <translation>Alle lesen</translation>
        </message>
        <message>
            <source>Read records 1..32 from the drive's EEPROM ('Z&lt;n&gt;|', 6.4)</source>
            <translation>Sätze 1..32 aus dem EEPROM des Antriebs lesen ('Z&lt;n&gt;|', 6.4)</translation>
        </message>
        <message>
            <source>Write record</source>
            <translation>Satz schreiben</translation>
        </message>
        <message>
            <source>Write the selected row into the record, store it and read it back (6.5)</source>
            <translation>Die gewählte Zeile in den Satz schreiben, speichern und zurücklesen (6.5)</translation>
        </message>
        <message>
            <source>Save to EEPROM</source>
            <translation>Im EEPROM speichern</translation>
        </message>
        <message>
            <source>Store the drive's current settings (RAM) as the selected record ('&gt;', 6.5)</source>
            <translation>Die aktuellen Einstellungen des Antriebs (RAM) als gewählten Satz speichern ('&gt;', 6.5)</translation>
        </message>
        <message>
            <source>Load record</source>
            <translation>Satz laden</translation>
        </message>
        <message>
            <source>Load the selected record into the drive's current settings ('y', 6.3)</source>
            <translation>Den gewählten Satz in die aktuellen Einstellungen des Antriebs laden ('y', 6.3)</translation>
        </message>
        <message>
            <source>Error memory</source>
            <translation>Fehlerspeicher</translation>
        </message>
        <message>
            <source>Read error memory</source>
            <translation>Fehlerspeicher lesen</translation>
        </message>
        <message>
            <source>Slot</source>
            <translation>Platz</translation>
        </message>
        <message>
            <source>Code</source>
            <translation>Code</translation>
        </message>
        <message>
            <source>Error</source>
            <translation>Fehler</translation>
        </message>
        <message>
            <source>Meaning</source>
            <translation>Bedeutung</translation>
        </message>
        <message>
            <source>Axis %1</source>
            <translation>Achse %1</translation>
        </message>
        <message>
            <source>Reading records 1..%1 of axis %2…</source>
            <translation>Lese Sätze 1..%1 der Achse %2…</translation>
        </message>
        <message>
            <source>Read the records first: there is nothing to write for record %1.</source>
            <translation>Zuerst die Sätze lesen: für Satz %1 gibt es nichts zu schreiben.</translation>
        </message>
        <message>
            <source>Writing record %1…</source>
            <translation>Schreibe Satz %1…</translation>
        </message>
        <message>
            <source>Saving the current settings as record %1…</source>
            <translation>Speichere die aktuellen Einstellungen als Satz %1…</translation>
        </message>
        <message>
            <source>Loading record %1…</source>
            <translation>Lade Satz %1…</translation>
        </message>
        <message>
            <source>Reading the error memory…</source>
            <translation>Lese den Fehlerspeicher…</translation>
        </message>
        <message>
            <source>Failed: %1</source>
            <translation>Fehlgeschlagen: %1</translation>
        </message>
        <message numerus="yes">
            <source>%n record(s) read.</source>
            <translation>
                <numerusform>%n Satz gelesen.</numerusform>
                <numerusform>%n Sätze gelesen.</numerusform>
            </translation>
        </message>
        <message>
            <source>Record %1 written, saved and verified.</source>
            <translation>Satz %1 geschrieben, gespeichert und geprüft.</translation>
        </message>
        <message>
            <source>Current settings saved as record %1.</source>
            <translation>Aktuelle Einstellungen als Satz %1 gespeichert.</translation>
        </message>
        <message>
            <source>Record %1 loaded into the drive's current settings.</source>
            <translation>Satz %1 in die aktuellen Einstellungen des Antriebs geladen.</translation>
        </message>
        <message>
            <source>Last entry: slot %1</source>
            <translation>Letzter Eintrag: Platz %1</translation>
        </message>
        <message>
            <source>Type part of a drive's name</source>
            <translation>Teil eines Antriebsnamens eingeben</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ReferencePanel</name>
        <message>
            <source>Reference all</source>
            <translation>Alle referenzieren</translation>
        </message>
        <message>
            <source>Cancel</source>
            <translation>Abbrechen</translation>
        </message>
        <message>
            <source>Referencing cancelled.</source>
            <translation>Referenzfahrt abgebrochen.</translation>
        </message>
        <message>
            <source>the panic stop</source>
            <translation>Panik-Stopp</translation>
        </message>
        <message>
            <source>the link is down</source>
            <translation>Verbindung getrennt</translation>
        </message>
        <message>
            <source>a panic stop, reset or limit switch</source>
            <translation>Panik-Stopp, Reset oder Endschalter</translation>
        </message>
        <message>
            <source>The axes are no longer referenced (%1): reference them again.</source>
            <translation>Die Achsen sind nicht mehr referenziert (%1): erneut referenzieren.</translation>
        </message>
        <message>
            <source>Referencing refused: %1</source>
            <translation>Referenzfahrt abgelehnt: %1</translation>
        </message>
        <message>
            <source>Referencing %1…</source>
            <translation>Referenzfahrt %1…</translation>
        </message>
        <message>
            <source>Every axis of the machine is referenced.</source>
            <translation>Alle Achsen der Maschine sind referenziert.</translation>
        </message>
        <message>
            <source>Referencing failed: %1</source>
            <translation>Referenzfahrt fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>%1 referenced.</source>
            <translation>%1 referenziert.</translation>
        </message>
        <message>
            <source>Reference every axis of the machine in the order and directions of its description (equal orders run together)</source>
            <translation>Jede Achse der Maschine in der Reihenfolge und Richtung ihrer Beschreibung referenzieren (gleiche Reihenfolge läuft gemeinsam)</translation>
        </message>
        <message>
            <source>Referencing…</source>
            <translation>Referenzieren…</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::SafetyBanner</name>
        <message>
            <source>the controller may still be moving: use the machine's emergency stop</source>
            <translation>die Steuerung bewegt sich möglicherweise noch: den Not-Aus der Maschine benutzen</translation>
        </message>
        <message>
            <source>Link lost while the machine was moving: %1. Positions are unknown: reconnect, then reference all axes.</source>
            <translation>Verbindung während einer Bewegung verloren: %1. Die Positionen sind unbekannt: neu verbinden, dann alle Achsen referenzieren.</translation>
        </message>
        <message>
            <source>Link lost: positions are unknown. Reconnect, then reference all axes.</source>
            <translation>Verbindung verloren: die Positionen sind unbekannt. Neu verbinden, dann alle Achsen referenzieren.</translation>
        </message>
        <message>
            <source>Disconnected while the machine was moving: no standstill was confirmed; %1.</source>
            <translation>Während einer Bewegung getrennt: kein Stillstand wurde bestätigt; %1.</translation>
        </message>
        <message>
            <source>Connecting…</source>
            <translation>Verbinde…</translation>
        </message>
        <message>
            <source>Not connected.</source>
            <translation>Nicht verbunden.</translation>
        </message>
        <message>
            <source>No standstill confirmed by the controller: %1.</source>
            <translation>Die Steuerung hat keinen Stillstand bestätigt: %1.</translation>
        </message>
        <message>
            <source>PANIC STOP sent: positions are lost; reference all axes before any absolute move.</source>
            <translation>PANIK-STOPP gesendet: die Positionen sind verloren; vor jeder Absolutfahrt alle Achsen referenzieren.</translation>
        </message>
        <message>
            <source>EMERGENCY STOP active on the machine: positions are lost. Release the emergency stop, then reference all axes.</source>
            <translation>NOT-AUS an der Maschine aktiv: die Positionen sind verloren. Den Not-Aus entriegeln, dann alle Achsen referenzieren.</translation>
        </message>
        <message>
            <source>Ready: all axes referenced.</source>
            <translation>Bereit: alle Achsen referenziert.</translation>
        </message>
        <message>
            <source>Positions are lost (panic stop or reconnect). Reference the machine before any absolute move.</source>
            <translation>Die Positionen sind verloren (Panik-Stopp oder Neuverbindung). Vor jeder Absolutfahrt die Maschine referenzieren.</translation>
        </message>
        <message>
            <source>Not referenced: positions are unknown until the axes are referenced.</source>
            <translation>Nicht referenziert: die Positionen sind unbekannt, bis die Achsen referenziert sind.</translation>
        </message>
        <message>
            <source>Setup incomplete: write the setup (start speed, max speed, acceleration) on the %1 page first. The controller refuses every move until then.</source>
            <translation>Einrichtung unvollständig: zuerst die Einrichtung (Startgeschwindigkeit, Maximalgeschwindigkeit, Beschleunigung) auf der Seite %1 schreiben. Bis dahin lehnt die Steuerung jede Fahrt ab.</translation>
        </message>
        <message>
            <source>Positions estimated, not confirmed by the controller: reference the axes before any absolute move.</source>
            <translation>Positionen geschätzt, nicht von der Steuerung bestätigt: vor jeder absoluten Bewegung die Achsen referenzieren.</translation>
        </message>
        <message>
            <source>Program running, line %1: STOP (Esc) ends it, Hold (F2) stops it on its path.</source>
            <translation>Programm läuft, Zeile %1: STOPP (Esc) beendet es, Halt (F2) hält es auf seiner Bahn an.</translation>
        </message>
        <message>
            <source>Program held at line %1: Resume goes on, STOP (Esc) ends it.</source>
            <translation>Programm hält in Zeile %1: Fortsetzen fährt weiter, STOPP (Esc) beendet es.</translation>
        </message>
        <message>
            <source>Program stopping at line %1: waiting for the axes to stand.</source>
            <translation>Programm stoppt in Zeile %1: wartet auf den Stillstand der Achsen.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::SafetyBar</name>
        <message>
            <source>STOP  (Esc)</source>
            <translation>STOPP  (Esc)</translation>
        </message>
        <message>
            <source>PANIC  (F1)</source>
            <translation>PANIK  (F1)</translation>
        </message>
        <message>
            <source>Ramped stop of all motion</source>
            <translation>Stopp aller Bewegungen mit Rampe</translation>
        </message>
        <message>
            <source>Immediate stop without ramp: steps are lost, the machine must be referenced afterwards</source>
            <translation>Sofortiger Stopp ohne Rampe: Schritte gehen verloren, die Maschine muss danach referenziert werden</translation>
        </message>
        <message>
            <source>STOP  (Esc)
does not stop the controller</source>
            <translation>STOPP  (Esc)
hält die Steuerung nicht an</translation>
        </message>
        <message>
            <source>PANIC  (F1)
does not stop the controller</source>
            <translation>PANIK  (F1)
hält die Steuerung nicht an</translation>
        </message>
        <message>
            <source>Ends every jog input and the host's queued work; %1</source>
            <translation>Beendet jede Tipp-Eingabe und die wartenden Aufträge des Rechners; %1</translation>
        </message>
        <message>
            <source>Reference all</source>
            <translation>Alle referenzieren</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::SdlGamepadDevice</name>
        <message>
            <source>SDL could not start its joystick support: %1</source>
            <translation>SDL konnte die Joystick-Unterstützung nicht starten: %1</translation>
        </message>
        <message>
            <source>This build has no gamepad support (SDL2 was not found when it was built).</source>
            <translation>Dieser Build hat keine Gamepad-Unterstützung (SDL2 wurde beim Bauen nicht gefunden).</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::SetupDriveChooser</name>
        <message>
            <source>Drives: name or address</source>
            <translation>Antriebe: Name oder Adresse</translation>
        </message>
        <message>
            <source>The setup shows the first %1 drives whose name or bus address contains this text.</source>
            <translation>Die Einrichtung zeigt die ersten %1 Antriebe, deren Name oder Busadresse diesen Text enthält.</translation>
        </message>
        <message>
            <source>Drives shown:</source>
            <translation>Gezeigte Antriebe:</translation>
        </message>
        <message>
            <source>No drive matches “%1”; still shown: %2</source>
            <translation>Kein Antrieb passt zu „%1“; weiter gezeigt: %2</translation>
        </message>
        <message>
            <source>%1 (%2 of %3 drives)</source>
            <translation>%1 (%2 von %3 Antrieben)</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::SetupPage</name>
        <message>
            <source>Read</source>
            <translation>Lesen</translation>
        </message>
        <message>
            <source>Write</source>
            <translation>Schreiben</translation>
        </message>
        <message>
            <source>Write &amp;&amp; verify</source>
            <translation>Schreiben &amp;&amp; prüfen</translation>
        </message>
        <message>
            <source>Defaults</source>
            <translation>Standardwerte</translation>
        </message>
        <message>
            <source>Save to file…</source>
            <translation>In Datei speichern…</translation>
        </message>
        <message>
            <source>Load from file…</source>
            <translation>Aus Datei laden…</translation>
        </message>
        <message>
            <source>Read the values back from the controller</source>
            <translation>Werte aus der Steuerung zurücklesen</translation>
        </message>
        <message>
            <source>Write, then read back and compare where the protocol can</source>
            <translation>Schreiben, dann zurücklesen und vergleichen, wo das Protokoll es erlaubt</translation>
        </message>
        <message>
            <source>Fill the form with the model's default values (nothing is sent)</source>
            <translation>Formular mit den Standardwerten des Modells füllen (es wird nichts gesendet)</translation>
        </message>
        <message>
            <source>Cannot write: %1</source>
            <translation>Schreiben nicht möglich: %1</translation>
        </message>
        <message>
            <source>Not connected</source>
            <translation>Nicht verbunden</translation>
        </message>
        <message>
            <source>Not written: %1</source>
            <translation>Nicht geschrieben: %1</translation>
        </message>
        <message numerus="yes">
            <source>Writing and verifying %n parameter(s)…</source>
            <translation>
                <numerusform>Schreibe und prüfe %n Parameter…</numerusform>
                <numerusform>Schreibe und prüfe %n Parameter…</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>Writing %n parameter(s)…</source>
            <translation>
                <numerusform>Schreibe %n Parameter…</numerusform>
                <numerusform>Schreibe %n Parameter…</numerusform>
            </translation>
        </message>
        <message>
            <source>This controller cannot read parameters back.</source>
            <translation>Diese Steuerung kann Parameter nicht zurücklesen.</translation>
        </message>
        <message>
            <source>Reading…</source>
            <translation>Lese…</translation>
        </message>
        <message>
            <source>Write failed: %1</source>
            <translation>Schreiben fehlgeschlagen: %1</translation>
        </message>
        <message numerus="yes">
            <source>Read %n parameter(s).</source>
            <translation>
                <numerusform>%n Parameter gelesen.</numerusform>
                <numerusform>%n Parameter gelesen.</numerusform>
            </translation>
        </message>
        <message>
            <source>Not saved: %1</source>
            <translation>Nicht gespeichert: %1</translation>
        </message>
        <message>
            <source>Save parameters</source>
            <translation>Parameter speichern</translation>
        </message>
        <message>
            <source>Parameter files (*.json)</source>
            <translation>Parameterdateien (*.json)</translation>
        </message>
        <message>
            <source>Saved to %1.</source>
            <translation>Gespeichert in %1.</translation>
        </message>
        <message>
            <source>Load parameters</source>
            <translation>Parameter laden</translation>
        </message>
        <message>
            <source>Loaded %1 into the form.</source>
            <translation>%1 ins Formular geladen.</translation>
        </message>
        <message>
            <source>Not written: cancelled.</source>
            <translation>Nicht geschrieben: abgebrochen.</translation>
        </message>
        <message>
            <source>Write all</source>
            <translation>Alles schreiben</translation>
        </message>
        <message>
            <source>This controller cannot read parameters back: the fields show the defaults (or a loaded file) until written. After every connect, reset or power cycle nothing counts as written.</source>
            <translation>Diese Steuerung kann Parameter nicht zurücklesen: die Felder zeigen die Vorgabewerte (oder eine geladene Datei), bis sie geschrieben sind. Nach jedem Verbinden, Reset oder Aus- und Einschalten gilt nichts als geschrieben.</translation>
        </message>
        <message>
            <source>Write every value on the page to the controller</source>
            <translation>Jeden Wert der Seite zur Steuerung schreiben</translation>
        </message>
        <message>
            <source>Write what is changed or not known to be on the controller</source>
            <translation>Schreiben, was geändert ist oder von dem nicht bekannt ist, dass es in der Steuerung steht</translation>
        </message>
        <message>
            <source>Read failed: %1. Values that could not be read are shown as unknown; they are written only if you set them.</source>
            <translation>Lesen fehlgeschlagen: %1. Werte, die nicht gelesen werden konnten, werden als unbekannt angezeigt; sie werden nur geschrieben, wenn Sie sie setzen.</translation>
        </message>
        <message>
            <source>Invalid values cannot be written (%1): %2</source>
            <translation>Ungültige Werte können nicht geschrieben werden (%1): %2</translation>
        </message>
        <message>
            <source>This controller's protocol has no parameters to set: there is nothing to write, read, save or load here.</source>
            <translation>Das Protokoll dieser Steuerung hat keine einstellbaren Parameter: Hier gibt es nichts zu schreiben, zu lesen, zu speichern oder zu laden.</translation>
        </message>
        <message>
            <source>Write or undo the changes of %1 before showing other drives.</source>
            <translation>Schreiben oder verwerfen Sie die Änderungen an %1, bevor andere Antriebe gezeigt werden.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ShortcutsDialog</name>
        <message>
            <source>Keyboard jog, while it is on: hold the key to move</source>
            <translation>Tastatur-Tippbetrieb, wenn eingeschaltet: Taste halten, um zu fahren</translation>
        </message>
        <message>
            <source>Keyboard shortcuts</source>
            <translation>Tastenkürzel</translation>
        </message>
        <message>
            <source>Key</source>
            <translation>Taste</translation>
        </message>
        <message>
            <source>Action</source>
            <translation>Aktion</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::SimulatorMenu</name>
        <message>
            <source>Si&amp;mulator</source>
            <translation>Si&amp;mulator</translation>
        </message>
        <message>
            <source>No built-in simulator is connected</source>
            <translation>Kein eingebauter Simulator verbunden</translation>
        </message>
        <message>
            <source>The simulated machine has no inputs to set</source>
            <translation>Die simulierte Maschine hat keine setzbaren Eingänge</translation>
        </message>
        <message>
            <source>%1: input %2 high</source>
            <translation>%1: Eingang %2 high</translation>
        </message>
        <message>
            <source>Input %1 high</source>
            <translation>Eingang %1 high</translation>
        </message>
        <message>
            <source>Checked as the controller last reported the input</source>
            <translation>Angehakt, wie die Steuerung den Eingang zuletzt gemeldet hat</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::SpindleCoolantBar</name>
        <message>
            <source>S </source>
            <translation>S </translation>
        </message>
        <message>
            <source>The speed the spindle switch starts it at, as a program's M3 S</source>
            <translation>Die Drehzahl, mit der der Spindelschalter sie startet, wie M3 S eines Programms</translation>
        </message>
        <message>
            <source>Spindle on</source>
            <translation>Spindel ein</translation>
        </message>
        <message>
            <source>Spindle off</source>
            <translation>Spindel aus</translation>
        </message>
        <message>
            <source>Coolant on</source>
            <translation>Kühlmittel ein</translation>
        </message>
        <message>
            <source>Coolant off</source>
            <translation>Kühlmittel aus</translation>
        </message>
        <message>
            <source>Spindle: unknown</source>
            <translation>Spindel: unbekannt</translation>
        </message>
        <message>
            <source>Coolant: unknown</source>
            <translation>Kühlmittel: unbekannt</translation>
        </message>
        <message>
            <source> rpm</source>
            <translation> U/min</translation>
        </message>
        <message>
            <source>Spindle: on</source>
            <translation>Spindel: ein</translation>
        </message>
        <message>
            <source>Spindle: off</source>
            <translation>Spindel: aus</translation>
        </message>
        <message>
            <source>As the controller reports it</source>
            <translation>Wie die Steuerung sie meldet</translation>
        </message>
        <message>
            <source>No connected controller of this machine has a spindle</source>
            <translation>Keine verbundene Steuerung dieser Maschine hat eine Spindel</translation>
        </message>
        <message>
            <source>No machine is open</source>
            <translation>Keine Maschine ist geöffnet</translation>
        </message>
        <message>
            <source>Coolant: on</source>
            <translation>Kühlmittel: ein</translation>
        </message>
        <message>
            <source>Coolant: off</source>
            <translation>Kühlmittel: aus</translation>
        </message>
        <message>
            <source>As last switched in this session: the controller cannot read its relay back</source>
            <translation>Wie zuletzt in dieser Sitzung geschaltet: die Steuerung kann ihr Relais nicht zurücklesen</translation>
        </message>
        <message>
            <source>No connected controller of this machine has coolant</source>
            <translation>Keine verbundene Steuerung dieser Maschine hat Kühlmittel</translation>
        </message>
        <message>
            <source>Laser on</source>
            <translation>Laser ein</translation>
        </message>
        <message>
            <source>Laser off</source>
            <translation>Laser aus</translation>
        </message>
        <message>
            <source>Laser: unknown</source>
            <translation>Laser: unbekannt</translation>
        </message>
        <message>
            <source>Laser: on</source>
            <translation>Laser: ein</translation>
        </message>
        <message>
            <source>Laser: off</source>
            <translation>Laser: aus</translation>
        </message>
        <message>
            <source>The power the laser switch turns the beam on at, as a program's M3 S</source>
            <translation>Die Leistung, mit der der Laserschalter den Strahl einschaltet, wie das M3 S eines Programms</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::StatusPanel</name>
        <message>
            <source>Drive on</source>
            <translation>Antrieb ein</translation>
        </message>
        <message>
            <source>The motors are powered.</source>
            <translation>Die Motoren sind bestromt.</translation>
        </message>
        <message>
            <source>Spindle on</source>
            <translation>Spindel ein</translation>
        </message>
        <message>
            <source>The spindle output is on.</source>
            <translation>Der Spindelausgang ist eingeschaltet.</translation>
        </message>
        <message>
            <source>Busy</source>
            <translation>Beschäftigt</translation>
        </message>
        <message>
            <source>An axis is moving.</source>
            <translation>Eine Achse ist in Bewegung.</translation>
        </message>
        <message>
            <source>Over-temperature</source>
            <translation>Übertemperatur</translation>
        </message>
        <message>
            <source>The controller reports over-temperature; the drivers may switch off.</source>
            <translation>Die Steuerung meldet Übertemperatur; die Endstufen können abschalten.</translation>
        </message>
        <message>
            <source>Setup incomplete</source>
            <translation>Einrichtung unvollständig</translation>
        </message>
        <message>
            <source>Speeds and acceleration have not all been written; moves are refused.</source>
            <translation>Geschwindigkeiten und Beschleunigung sind nicht alle geschrieben; Fahrten werden abgelehnt.</translation>
        </message>
        <message>
            <source>Emergency stop</source>
            <translation>Not-Aus</translation>
        </message>
        <message>
            <source>Emergency stop active: panic button or host panic stop.</source>
            <translation>Not-Aus aktiv: Panik-Taster oder Panik-Stopp vom PC.</translation>
        </message>
        <message>
            <source>Comm fault</source>
            <translation>Kommunikationsfehler</translation>
        </message>
        <message>
            <source>Replies are missing or the link is lost.</source>
            <translation>Antworten fehlen oder die Verbindung ist verloren.</translation>
        </message>
        <message>
            <source>Start button</source>
            <translation>Starttaste</translation>
        </message>
        <message>
            <source>The start button on the controller is pressed.</source>
            <translation>Die Starttaste an der Steuerung ist gedrückt.</translation>
        </message>
        <message>
            <source>Moving</source>
            <translation>Fährt</translation>
        </message>
        <message>
            <source>Positioning, feed, reference or velocity move</source>
            <translation>Positionier-, Vorschub-, Referenz- oder Geschwindigkeitsfahrt</translation>
        </message>
        <message>
            <source>Jog</source>
            <translation>Tippen</translation>
        </message>
        <message>
            <source>Jogging at a non-zero rate</source>
            <translation>Tippbetrieb mit einer Rate ungleich null</translation>
        </message>
        <message>
            <source>Limit</source>
            <translation>Endschalter</translation>
        </message>
        <message>
            <source>A limit switch of this axis is active</source>
            <translation>Ein Endschalter dieser Achse ist aktiv</translation>
        </message>
        <message>
            <source>Ref. switch</source>
            <translation>Ref.-Schalter</translation>
        </message>
        <message>
            <source>The reference switch is active</source>
            <translation>Der Referenzschalter ist aktiv</translation>
        </message>
        <message>
            <source>Referenced</source>
            <translation>Referenziert</translation>
        </message>
        <message>
            <source>Referenced since the last panic, reset or reconnect</source>
            <translation>Referenziert seit dem letzten Panik-Stopp, Reset oder Neuverbinden</translation>
        </message>
        <message>
            <source>Raw status</source>
            <translation>Rohstatus</translation>
        </message>
        <message>
            <source>Machine</source>
            <translation>Maschine</translation>
        </message>
        <message>
            <source>Axes</source>
            <translation>Achsen</translation>
        </message>
        <message>
            <source>Controller</source>
            <translation>Steuerung</translation>
        </message>
        <message>
            <source>Temperature:</source>
            <translation>Temperatur:</translation>
        </message>
        <message>
            <source>no raw words</source>
            <translation>keine Rohwerte</translation>
        </message>
        <message>
            <source>Comm faults: %1    Resyncs: %2    Poll rate: %3 Hz</source>
            <translation>Kommunikationsfehler: %1    Neusynchronisierungen: %2    Abfragerate: %3 Hz</translation>
        </message>
        <message>
            <source>Drive %1: %2 %3</source>
            <translation>Antrieb %1: %2 %3</translation>
        </message>
        <message>
            <source>responding</source>
            <translation>antwortet</translation>
        </message>
        <message>
            <source>NOT RESPONDING</source>
            <translation>ANTWORTET NICHT</translation>
        </message>
        <message>
            <source>Over-temperature: the drivers may switch off. Stop and let the controller cool down.</source>
            <translation>Übertemperatur: die Endstufen können abschalten. Anhalten und die Steuerung abkühlen lassen.</translation>
        </message>
        <message>
            <source>Warning: approaching the %1 °C over-temperature limit.</source>
            <translation>Warnung: nahe an der Übertemperaturgrenze von %1 °C.</translation>
        </message>
        <message>
            <source>Motion unconfirmed</source>
            <translation>Bewegung unbestätigt</translation>
        </message>
        <message>
            <source>The controller did not confirm that the machine stands still (a move never reported its arrival, or the link was lost while it ran): it may still be moving.</source>
            <translation>Die Steuerung hat nicht bestätigt, dass die Maschine stillsteht (eine Fahrt hat ihre Ankunft nie gemeldet, oder die Verbindung brach während der Fahrt ab): sie bewegt sich womöglich noch.</translation>
        </message>
        <message>
            <source>Door open</source>
            <translation>Tür offen</translation>
        </message>
        <message>
            <source>The door switch reports the door open (grey: not reported yet).</source>
            <translation>Der Türschalter meldet die Tür offen (grau: noch nicht gemeldet).</translation>
        </message>
        <message>
            <source>Firmware: %1</source>
            <translation>Firmware: %1</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::StoredParametersBar</name>
        <message>
            <source>Store as power-on values…</source>
            <translation>Als Einschaltwerte speichern…</translation>
        </message>
        <message>
            <source>Read stored values</source>
            <translation>Gespeicherte Werte lesen</translation>
        </message>
        <message>
            <source>Write the form's values into the controller's own memory: it starts with them after every power-on</source>
            <translation>Die Werte des Formulars in den Speicher der Steuerung schreiben: sie startet nach jedem Einschalten mit ihnen</translation>
        </message>
        <message>
            <source>Read the values stored in the controller into the form</source>
            <translation>Die in der Steuerung gespeicherten Werte ins Formular lesen</translation>
        </message>
        <message>
            <source>Invalid values cannot be stored: %1</source>
            <translation>Ungültige Werte können nicht gespeichert werden: %1</translation>
        </message>
        <message>
            <source>Store power-on values</source>
            <translation>Einschaltwerte speichern</translation>
        </message>
        <message>
            <source>Store the form's values in the controller? It starts with them after every power-on. Values without a stored form are left out.%1</source>
            <translation>Die Werte des Formulars in der Steuerung speichern? Sie startet nach jedem Einschalten mit ihnen. Werte ohne gespeicherte Form werden ausgelassen.%1</translation>
        </message>
        <message>
            <source>Not stored: cancelled.</source>
            <translation>Nicht gespeichert: abgebrochen.</translation>
        </message>
        <message>
            <source>Storing…</source>
            <translation>Wird gespeichert…</translation>
        </message>
        <message>
            <source>Reading the stored values…</source>
            <translation>Die gespeicherten Werte werden gelesen…</translation>
        </message>
        <message>
            <source>Not stored: %1</source>
            <translation>Nicht gespeichert: %1</translation>
        </message>
        <message>
            <source>Stored as power-on values.</source>
            <translation>Als Einschaltwerte gespeichert.</translation>
        </message>
        <message>
            <source>Stored as power-on values; not stored (no stored form): %1.</source>
            <translation>Als Einschaltwerte gespeichert; nicht gespeichert (keine gespeicherte Form): %1.</translation>
        </message>
        <message>
            <source>Reading the stored values failed: %1</source>
            <translation>Das Lesen der gespeicherten Werte ist fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>Nothing is stored: the controller starts with its defaults.</source>
            <translation>Nichts gespeichert: die Steuerung startet mit ihren Standardwerten.</translation>
        </message>
        <message>
            <source>Stored values in the form: %1.%2</source>
            <translation>Gespeicherte Werte im Formular: %1.%2</translation>
        </message>
        <message>
            <source>Not stored: not connected.</source>
            <translation>Nicht gespeichert: nicht verbunden.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::ToolTableDialog</name>
        <message>
            <source>Tool table</source>
            <translation>Werkzeugtabelle</translation>
        </message>
        <message>
            <source>One tool a line, as in LinuxCNC's tool.tbl: T&lt;number&gt; Z&lt;length&gt; D&lt;diameter&gt; ;text. G43 offsets Z by the length (in Z's unit); M6 shows the text when it asks for the tool.</source>
            <translation>Ein Werkzeug je Zeile, wie in LinuxCNCs tool.tbl: T&lt;Nummer&gt; Z&lt;Länge&gt; D&lt;Durchmesser&gt; ;Text. G43 versetzt Z um die Länge (in der Einheit von Z); M6 zeigt den Text, wenn es nach dem Werkzeug fragt.</translation>
        </message>
        <message>
            <source>The table was not saved.</source>
            <translation>Die Tabelle wurde nicht gespeichert.</translation>
        </message>
        <message>
            <source>Not saved: %1</source>
            <translation>Nicht gespeichert: %1</translation>
        </message>
        <message>
            <source>Another machine was opened: its table is shown; the unsaved edits were for the previous one and are dropped.</source>
            <translation>Eine andere Maschine wurde geöffnet: Ihre Tabelle wird gezeigt; die ungespeicherten Änderungen galten der vorigen und wurden verworfen.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::TrafficConsole</name>
        <message>
            <source>Hex</source>
            <translation>Hex</translation>
        </message>
        <message>
            <source>Hide polls</source>
            <translation>Abfragen ausblenden</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>Send</source>
            <translation>Senden</translation>
        </message>
        <message>
            <source>Clear</source>
            <translation>Leeren</translation>
        </message>
        <message>
            <source>Save…</source>
            <translation>Speichern…</translation>
        </message>
        <message>
            <source>Hide the status poller's requests and replies</source>
            <translation>Anfragen und Antworten der Statusabfrage ausblenden</translation>
        </message>
        <message>
            <source>Freeze the view; traffic is still recorded</source>
            <translation>Ansicht einfrieren; der Datenverkehr wird weiter aufgezeichnet</translation>
        </message>
        <message numerus="yes">
            <source>%n record(s)</source>
            <translation>
                <numerusform>%n Eintrag</numerusform>
                <numerusform>%n Einträge</numerusform>
            </translation>
        </message>
        <message>
            <source>Not sent: %1</source>
            <translation>Nicht gesendet: %1</translation>
        </message>
        <message>
            <source>Not sent: not connected</source>
            <translation>Nicht gesendet: nicht verbunden</translation>
        </message>
        <message>
            <source>Send failed: %1</source>
            <translation>Senden fehlgeschlagen: %1</translation>
        </message>
        <message>
            <source>Cannot write %1: %2</source>
            <translation>%1 kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>Save traffic</source>
            <translation>Datenverkehr speichern</translation>
        </message>
        <message>
            <source>Log files (*.log *.txt)</source>
            <translation>Protokolldateien (*.log *.txt)</translation>
        </message>
        <message>
            <source>Send raw bytes: text as it is, \r for CR, &lt;xNN&gt; for any other byte.</source>
            <translation>Rohe Bytes senden: Text wie er ist, \r für CR, &lt;xNN&gt; für jedes andere Byte.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::WorkspaceFit</name>
        <message>
            <source>Jog controls</source>
            <translation>Tipp-Bedienelemente</translation>
        </message>
        <message>
            <source>The window is too small for these pages, they scroll: %1. A larger window, or View &gt; Reset layout, gives them room.</source>
            <translation>Das Fenster ist zu klein für diese Seiten, sie rollen: %1. Ein größeres Fenster oder Ansicht &gt; Layout zurücksetzen gibt ihnen Platz.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::Workspaces</name>
        <message>
            <source>Run</source>
            <translation>Betrieb</translation>
        </message>
        <message>
            <source>Setup</source>
            <translation>Einrichten</translation>
        </message>
        <message>
            <source>The program, its preview, the position and the jog pad (Ctrl+1)</source>
            <translation>Das Programm, seine Vorschau, die Position und das Jog-Feld (Strg+1)</translation>
        </message>
        <message>
            <source>Parameters, drives, records, traffic, charts and status (Ctrl+2)</source>
            <translation>Parameter, Antriebe, Sätze, Verkehr, Diagramme und Status (Strg+2)</translation>
        </message>
        <message>
            <source>&amp;Run workspace</source>
            <translation>&amp;Arbeitsbereich Betrieb</translation>
        </message>
        <message>
            <source>&amp;Setup workspace</source>
            <translation>Arbeitsbereich &amp;Einrichten</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::WritePlan</name>
        <message>
            <source>Nothing to write: every value was written or read in this session and nothing changed since.</source>
            <translation>Nichts zu schreiben: jeder Wert wurde in dieser Sitzung geschrieben oder gelesen, und seitdem hat sich nichts geändert.</translation>
        </message>
        <message numerus="yes">
            <source>Nothing to write: %n value(s) could not be read (%1); they are written only once you set them.</source>
            <translation>
                <numerusform>Nichts zu schreiben: %n Wert konnte nicht gelesen werden (%1); er wird erst geschrieben, wenn Sie ihn setzen.</numerusform>
                <numerusform>Nichts zu schreiben: %n Werte konnten nicht gelesen werden (%1); sie werden erst geschrieben, wenn Sie sie setzen.</numerusform>
            </translation>
        </message>
        <message>
            <source>Nothing to write: every field matches the controller.</source>
            <translation>Nichts zu schreiben: jedes Feld stimmt mit der Steuerung überein.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::WritePreview</name>
        <message>
            <source>on</source>
            <translation>ein</translation>
        </message>
        <message>
            <source>off</source>
            <translation>aus</translation>
        </message>
        <message>
            <source>all</source>
            <translation>alle</translation>
        </message>
        <message>
            <source>Drive %1 (%2)</source>
            <translation>Antrieb %1 (%2)</translation>
        </message>
        <message>
            <source>Write parameters</source>
            <translation>Parameter schreiben</translation>
        </message>
        <message numerus="yes">
            <source>These %n value(s) will be sent, and nothing else:</source>
            <translation>
                <numerusform>Dieser %n Wert wird gesendet, sonst nichts:</numerusform>
                <numerusform>Diese %n Werte werden gesendet, sonst nichts:</numerusform>
            </translation>
        </message>
        <message>
            <source>Drive</source>
            <translation>Antrieb</translation>
        </message>
        <message>
            <source>Parameter</source>
            <translation>Parameter</translation>
        </message>
        <message>
            <source>Unit</source>
            <translation>Einheit</translation>
        </message>
        <message>
            <source>Please read before writing:&lt;br&gt;%1</source>
            <translation>Bitte vor dem Schreiben lesen:&lt;br&gt;%1</translation>
        </message>
        <message>
            <source>Write</source>
            <translation>Schreiben</translation>
        </message>
        <message>
            <source>%1 (written, not read back)</source>
            <translation>%1 (geschrieben, nicht zurückgelesen)</translation>
        </message>
        <message>
            <source>unknown (not read)</source>
            <translation>unbekannt (nicht gelesen)</translation>
        </message>
        <message>
            <source>unknown (cannot be read back)</source>
            <translation>unbekannt (kann nicht zurückgelesen werden)</translation>
        </message>
        <message>
            <source>Old</source>
            <translation>Alt</translation>
        </message>
        <message>
            <source>New</source>
            <translation>Neu</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::WriteResultText</name>
        <message>
            <source>Written: %1.</source>
            <translation>Geschrieben: %1.</translation>
        </message>
        <message>
            <source>Written: %1. Nothing could be verified: this controller cannot read these values back.</source>
            <translation>Geschrieben: %1. Nichts konnte geprüft werden: Diese Steuerung kann diese Werte nicht zurücklesen.</translation>
        </message>
        <message>
            <source>Written and verified by reading back: %1.</source>
            <translation>Geschrieben und durch Zurücklesen geprüft: %1.</translation>
        </message>
        <message>
            <source>Written and verified by reading back: %1. Written but not verified (this controller cannot read them back): %2.</source>
            <translation>Geschrieben und durch Zurücklesen geprüft: %1. Geschrieben, aber nicht geprüft (diese Steuerung kann sie nicht zurücklesen): %2.</translation>
        </message>
    </context>
    <context>
        <name>stepdeck::ui::WriteWarnings</name>
        <message>
            <source>Write parameters</source>
            <translation>Parameter schreiben</translation>
        </message>
        <message>
            <source>Please read before writing:&lt;br&gt;&lt;br&gt;%1</source>
            <translation>Bitte vor dem Schreiben lesen:&lt;br&gt;&lt;br&gt;%1</translation>
        </message>
    </context>
</TS>
