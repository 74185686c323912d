#!/usr/bin/env python3
"""Writes the seed corpora (corpus/<target>/) and dictionaries (dict/<target>.dict) of the
libFuzzer targets from the manuals' own examples. Run it after changing the examples below;
its output is committed (small files). tools/fuzz never changes corpus/: the fuzzers write
what they find into build-fuzz/corpus/<target>/.

  tests/fuzz/make_seeds.py
"""
import json
import os
import shutil

HERE = os.path.dirname(os.path.abspath(__file__))
CTRL = {name: i for i, name in enumerate(
    "NUL SOH STX ETX EOT ENQ ACK BEL BS HT LF VT FF CR SO SI DLE XON DC2 XOFF DC4 NAK SYN "
    "ETB CAN EM SUB ESC FS GS RS US".split())}
CTRL.update(DC1=0x11, DC3=0x13)  # the EMIS manual's names of XON and XOFF


def mnemonics(text):
    """'<ENQ>0080#' -> bytes, as the E-LAB manual writes frames."""
    out = bytearray()
    i = 0
    while i < len(text):
        if text[i] == "<":
            end = text.index(">", i)
            name = text[i + 1:end]
            out.append(int(name[1:], 16) if name.startswith("x") else CTRL[name])
            i = end + 1
        else:
            out += text[i].encode("latin-1")
            i += 1
    return bytes(out)


# E-LAB manual, "Allgemeine Befehle" and the command sections: replies ...
ELAB_REPLIES = [
    "<ACK>", "<NAK>", "<XON>", "<XOFF>",
    "<ETX>1F1F1F1F,1E1E1E1E;FFFFFFFF.", "<ETX>FFFFFFFF,00000010;000000FF.",
    "<ETB>14#", "<ENQ>0080#", "<HT>05#", "<HT>02#",
    "<ENQ>0080#<HT>05#<ETB>14#<ACK><NAK>",
    "<ENQ>00<HT>05#",            # interrupted by a new control byte
    "garbage<ACK>",              # bytes outside a reply, then resynchronised
    "<ETX>0000000g,00000000;00000000.",  # malformed hex
]
# ... and commands (host -> controller), including the manual's spaces ("<SO>FF, FF;00.").
ELAB_COMMANDS = [
    "<DC4>1F1F1F1F,1E1E1E1E;FFFFFFFF.", "<SO>FF, FF;00.", "<SO>00,00;00.", "<DLE>FF,FF;FF.",
    "<ESC>S0064,0064;0064.", "<ESC>M1388,1388;1388.", "<ESC>A03E8,03E8;03E8.",
    "<FS>0064,0064;0064.", "<STX>64", "<SOH>000003E8#", "<SI>FF", "<SI>00", "<BEL>", "<XOFF>",
    "<GS>", "<FF>000003E8,FFFFFC18;", "<EOT>000003E8,FFFFFC18;00000010.", "<BS>000003E8.",
    "<RS>", "<EM>000003E8,", "<SUB>000003E8;", "<VT>000003E8.", "<DC2><x11><DC2><x25><CR>",
    "<DC4>0064,0064;FF9C.", "<US>FFFF,0000;0001.", "<CAN>FC18,0000;03e9.",
    "<ENQ><HT><ETB><ETX><LF><SYN><SYN><SYN>", "<DC2><x88>", "<ESC>X0064,0064;0064.",
]
# Nanotec manual: 1.1/1.2 frames, 3 (read), 5.15, 5.19, 5.21, 5.22, 6.4 (records).
NANOTEC_REPLIES = [
    "001s1000\r", "001A\r", "001/?\r", "1:?\r", "1:CL_motor_pp+50\r", "1:CL_motor_pp=100\r",
    "001Zs1000\r", "001Z5s2000\r", "001v PD4_RS485_26-09-2007\r", "1L0\r", "1L20\r",
    "Zp+1s+1u+400o+860n+1000b+55800d+1t+0W+1P+0N+0\r",
    "Z5p+1s+400u+400o+1000n+1000b+2364d+0t+0W+1P+0N+0\r",
    "001$17\r", "002j33\r", "254C-1500\r", "001ZE5+8\r", "001E5\r", "#1A\r",
    "001Z0E1s0\r", "noise\r001$17\r", "001s1000\n\r\x00002A\r",
]
NANOTEC_COMMANDS = [
    "#1s1000\r", "#1A\r", "#1/\r", "#*S\r", "#1:CL_motor_pp\r", "#1:CL_motor_pp=100\r",
    "#1Zs\r", "#1Z5s\r", "#1L0\r", "#1ZE5\r", "#1Z|\r", "#1Z5|\r", "#254s-50\r", "#3$\r",
    "#1|0\r", "#1@A\r", "noise#1s10#2A\r#x\r#3\r", "##1A\r",
]
# EMIS SMC-IC4 manual, chapter 9: commands (host -> board) of 9.1-9.18, the input programs of
# 9.17 with their <STX> headers and <ETX>, and malformed ones ...
EMIS_COMMANDS = [
    "@V<CR>", "@I1<CR>", "@IG<CR>", "A1,1<CR>", "#S200<CR>", "#S,x200<CR>", "#E1,1000<CR>",
    "#E1,x1000<CR>", "#E9,400<CR>", "#R100<CR>", "D,x32<CR>", "c,x100,20<CR>", "$Hx<CR>",
    "$Hxyzu<CR>", "$Hxyzu,a<CR>", "#Ox,10<CR>", "L1,x1000<CR>", "L1,x-1000<CR>",
    "L1,x1000,y-2000<CR>", "L1,X1000<CR>", "IP1<CR>", "W500<CR>", "##D,x32,y16,z64,u1<CR>",
    "##c,x100,0,y100,0,z100,20,u100,0<CR>", "##REFSW,xNO,yNO,zNO,uNC<CR>",
    "##S,x200,y200,z200,u200<CR>", "##E,x1800,y1800,z600,u1000<CR>",
    "##E9,x400,y400,z200,u300<CR>", "##R,100<CR>", "##S,200,1800,100<CR>", "*PRSYS<CR>",
    "*PESYS<CR>",
    "*PWIN7<CR>IJ7,1 Eingang 7: Referenzfahrt X-Motor <STX>$H,x<CR><ETX>",
    "*PWIN8<CR>IJ8,1 Eingang 8: Vektorfahrt X-Motor <STX>L1,x191<CR>W1500<CR><ETX>",
    "*PEIN1<CR>", "@V<CR><LF>@IG<CR><LF>", "L1,x+0001000,x5<CR>", "$Hxx<CR>", "A9,2<CR>",
    "W99999999999999999999<CR>", "D,X32<CR>", "#S,x<CR>", "IJ7<CR>", "text<ETX>",
]
# ... and replies (board -> host), as the manual prints them (with echoes and blanks).
EMIS_REPLIES = [
    "@V SMC-IC4 v1.07<ACK>", "@I1 0<ACK>", "@IG 10000000<ACK>", "<ACK>", "$Hx<NAK><DC1>",
    "$Hxyzu<NAK><DC1><DC2><DC3><DC4>", "$Hxyzu<NAK><DC4><DC2><DC1><DC3>", "<NAK> <DC1>",
    "<NAK> <DC1><DC2>", "<ACK> Ready! <ACK> <ACK> <ACK> <ACK>", "*PESYS <ACK>",
    "*PRSYS:##D,x32,y16,z64,u1<CR><LF>##R,100<CR><LF>##REFSW,xNO,yNO,zNO,uNC<ACK>",
    "*PRSYS:D,x32;c,x100,0,y100,0 ##S,200,1800,100##E9,x400<ACK>", "<BEL>", "A9,2<BEL>",
    "@IG 100<DC2>00000<ACK>", "garbage<x80><xFF>@V<ACK>", "@IG 1000 0000<ACK>",
]
LASER_COMMANDS = ["1100000\r", "2200150\r", "2399999\r", "1312345\r", "2100000\r\n",
                  "9100000\r", "2400000\r", "22001\r", "220015000000\r2100001\r",
                  "21x0000\r", "\r\r2200150"]
LASER_STATUS = ["2001500\r", "1000000\r", "1999991\r", "3000042\r", "2001503\r",
                "1123454\r\n", "2001505\r", "4000000\r", "200150\r", "20015000\r2001500\r",
                "20a1500\r"]
# The parameter-file format (docs/cli.md) with values of both models, and broken ones.
PARAMETER_FILES = [
    {"format": "stepdeck-parameters", "version": 1, "model": "elab",
     "parameters": {"start-speed": {"X": 100, "Y": 200, "Z": 300},
                    "limit-polarity": {"X": "high", "Y": "low", "Z": "low"},
                    "drive-power": 66, "coolant": True, "spindle-rpm": "0100"}},
    {"format": "stepdeck-parameters", "version": 1, "model": "nanotec",
     "parameters": {"phase-current": {"X": 50}, "step-mode": {"X": "adaptive"},
                    "motor-mode": {"X": "positioning"}, "ramp-mode": {"X": 1}}},
    {"drive-power": 1e300, "max-speed": {"X": -0.0, "Y": 12.5, "Z": "0x40"}},
    {"drive-power": "nan", "coolant": "yes", "start-speed": {"U": 1}},
]
ASSIGNMENTS = [
    "drive-power=0100", "drive-power=0x40", "drive-power=nan", "start-speed=100,200,300",
    "max-speed=+5000", "limit-polarity=high,low,high", "coolant=on", "spindle-rpm=1e3",
    "phase-current=50", "step-mode=adaptive", "step-angle=0.9", "motor-mode=speed",
    "acceleration=99999999999999999999", "feed-speed=-1", "=5", "start-speed",
    " 7 ", "-Infinity", ".5e-3",
]
DICTS = {
    "elab_reply": [mnemonics(f"<{n}>") for n in ("ACK", "NAK", "XON", "XOFF", "ENQ", "HT",
                                                   "ETB", "ETX")] + [b"#", b",", b";", b"."],
    "elab_command": [bytes([i]) for i in range(1, 32)] + [b"S", b"M", b"A", b"FF", b"00"],
    "nanotec_reply": [b"\r", b"001", b"Z", b"ZE", b":CL_", b"=", b"?", b"v ", b"+", b"-", b"|"]
    + [c.encode() for c in "psuonbdtWPN$CIAj"],
    "nanotec_command": [b"#", b"\r", b"*", b"Z", b"ZE", b":CL_motor_pp", b"=", b"|", b"@A"],
    "emis_command": [mnemonics(f"<{n}>") for n in ("CR", "STX", "ETX", "LF")]
    + [w.encode() for w in ("@V", "@I", "@IG", "A", "#S", "#S,", "#E1,", "#E9,", "#R", "D,",
                             "c,", "$H", ",a", "#O", "L1,", "IP", "W", "##", "REFSW", "NO",
                             "NC", "*PRSYS", "*PESYS", "*PWIN", "*PEIN", "IJ", ",1 ", "x",
                             "y", "z", "u", "X", "-", "+", ",")],
    "emis_reply": [mnemonics(f"<{n}>") for n in ("ACK", "NAK", "BEL", "DC1", "DC2", "DC3",
                                                   "DC4", "CR", "LF")]
    + [w.encode() for w in ("@V", "@IG", "@I1", "Ready!", "*PRSYS:", "*PESYS", "##", "D,",
                             "c,", "REFSW", "E9,", "R,", "S,", "x", "y", "z", "u", "NO", "NC")],
    "laser_command": [b"\r", b"\n", b"1", b"2", b"3", b"00000", b"99999"],
    "laser_status": [b"\r", b"\n", b"0", b"1", b"2", b"3", b"4", b"00000", b"99999"],
    "parameter_file": [b'"format"', b'"stepdeck-parameters"', b'"version"', b'"model"',
                       b'"elab"', b'"nanotec"', b'"parameters"', b'"X"', b'"Y"', b'"Z"',
                       b'"U"', b"1e300", b"-0.0", b"true", b"null", b'"drive-power"',
                       b'"start-speed"', b'"phase-current"', b'"step-mode"'],
    "assignment": [b"=", b",", b"+", b"-", b"0x", b"e", b"nan", b"inf", b"drive-power",
                   b"start-speed", b"limit-polarity", b"phase-current", b"step-mode",
                   b"coolant", b"high", b"low", b"on", b"off"],
}


def write(target, seeds):
    folder = os.path.join(HERE, "corpus", target)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    for i, seed in enumerate(seeds):
        with open(os.path.join(folder, f"seed-{i:02d}"), "wb") as f:
            f.write(seed)


def dictionary(target, words):
    os.makedirs(os.path.join(HERE, "dict"), exist_ok=True)
    with open(os.path.join(HERE, "dict", f"{target}.dict"), "w") as f:
        for w in words:
            f.write('"' + "".join(f"\\x{b:02X}" for b in w) + '"\n')


def main():
    write("elab_reply", [mnemonics(t) for t in ELAB_REPLIES])
    write("elab_command", [mnemonics(t) for t in ELAB_COMMANDS])
    write("nanotec_reply", [t.encode("latin-1") for t in NANOTEC_REPLIES])
    write("nanotec_command", [t.encode("latin-1") for t in NANOTEC_COMMANDS])
    write("emis_command", [mnemonics(t) for t in EMIS_COMMANDS])
    write("emis_reply", [mnemonics(t) for t in EMIS_REPLIES])
    write("laser_command", [t.encode() for t in LASER_COMMANDS])
    write("laser_status", [t.encode() for t in LASER_STATUS])
    write("parameter_file", [json.dumps(f).encode() for f in PARAMETER_FILES])
    write("assignment", [t.encode() for t in ASSIGNMENTS])
    for target, words in DICTS.items():
        dictionary(target, words)


if __name__ == "__main__":
    main()
