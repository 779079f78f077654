// The worked examples of docs/program.md (the specification's §8): each
// program in the text form and as the CSV data rows that follow the three
// header rows, copied verbatim from the specification's section 8 (data rows
// TAB-separated as printed there); a change there is a change here.
#pragma once

#include <array>
#include <string_view>

namespace slmp::program::test {

struct WorkedExample {
    std::string_view number;   // "8.1"
    std::string_view title;
    std::string_view text;     // the text form, one line each
    std::string_view csv_rows; // TAB-separated, LF-terminated data rows; empty: text form only
};

inline constexpr std::array<WorkedExample, 15> worked_examples{{
    {"8.1", "Self-holding circuit",
     R"~(LD X0
OR Y0
ANI X1
OUT Y0
END
)~",
     R"~("0"	""	"LD"	"X0"	""	""	""
"1"	""	"OR"	"Y0"	""	""	""
"2"	""	"ANI"	"X1"	""	""	""
"3"	""	"OUT"	"Y0"	""	""	""
"4"	""	"END"	""	""	""	""
)~"},
    {"8.2", "On-delay timer, K20 at 10 ms scans",
     R"~(LD X0
OUT T0 K20
LD T0
OUT Y0
END
)~",
     R"~("0"	""	"LD"	"X0"	""	""	""
"1"	""	"OUT"	"T0"	""	""	""
""	""	""	"K20"	""	""	""
"5"	""	"LD"	"T0"	""	""	""
"6"	""	"OUT"	"Y0"	""	""	""
"7"	""	"END"	""	""	""	""
)~"},
    {"8.3", "Counter K3 with reset",
     R"~(LD X0
OUT C0 K3
LD C0
OUT Y0
LD X1
RST C0
END
)~",
     R"~("0"	""	"LD"	"X0"	""	""	""
"1"	""	"OUT"	"C0"	""	""	""
""	""	""	"K3"	""	""	""
"5"	""	"LD"	"C0"	""	""	""
"6"	""	"OUT"	"Y0"	""	""	""
"7"	""	"LD"	"X1"	""	""	""
"8"	""	"RST"	"C0"	""	""	""
"9"	""	"END"	""	""	""	""
)~"},
    {"8.4", "Branches (MPS/MRD/MPP) and blocks (ANB/ORB)",
     R"~(LD X0
MPS
AND X1
OUT Y0
MRD
AND X2
OUT Y1
MPP
ANI X1
OUT Y2
LD X3
OR X4
LD X5
OR X6
ANB
LD X7
AND X10
ORB
OUT Y3
END
)~",
     R"~("0"	""	"LD"	"X0"	""	""	""
"1"	""	"MPS"	""	""	""	""
"2"	""	"AND"	"X1"	""	""	""
"3"	""	"OUT"	"Y0"	""	""	""
"4"	""	"MRD"	""	""	""	""
"5"	""	"AND"	"X2"	""	""	""
"6"	""	"OUT"	"Y1"	""	""	""
"7"	""	"MPP"	""	""	""	""
"8"	""	"ANI"	"X1"	""	""	""
"9"	""	"OUT"	"Y2"	""	""	""
"10"	""	"LD"	"X3"	""	""	""
"11"	""	"OR"	"X4"	""	""	""
"12"	""	"LD"	"X5"	""	""	""
"13"	""	"OR"	"X6"	""	""	""
"14"	""	"ANB"	""	""	""	""
"15"	""	"LD"	"X7"	""	""	""
"16"	""	"AND"	"X10"	""	""	""
"17"	""	"ORB"	""	""	""	""
"18"	""	"OUT"	"Y3"	""	""	""
"19"	""	"END"	""	""	""	""
)~"},
    {"8.5", "Master control",
     R"~(LD X0
MC N0 M100
LD X1
OUT Y0
LD X1
OUT T0 K5
LD X2
SET M0
MCR N0
LD M100
OUT Y1
END
)~",
     R"~("0"	""	"LD"	"X0"	""	""	""
"1"	""	"MC"	"N0"	""	""	""
""	""	""	"M100"	""	""	""
"4"	""	"LD"	"X1"	""	""	""
"5"	""	"OUT"	"Y0"	""	""	""
"6"	""	"LD"	"X1"	""	""	""
"7"	""	"OUT"	"T0"	""	""	""
""	""	""	"K5"	""	""	""
"11"	""	"LD"	"X2"	""	""	""
"12"	""	"SET"	"M0"	""	""	""
"13"	""	"MCR"	"N0"	""	""	""
"15"	""	"LD"	"M100"	""	""	""
"16"	""	"OUT"	"Y1"	""	""	""
"17"	""	"END"	""	""	""	""
)~"},
    {"8.6", "Conditional jump over a block",
     R"~(LD X0
CJ P10
LD X1
OUT Y0
LD SM400
INC D1
P10
LD SM400
INC D2
END
)~",
     R"~("0"	""	"LD"	"X0"	""	""	""
"1"	""	"CJ"	"P10"	""	""	""
"3"	""	"LD"	"X1"	""	""	""
"4"	""	"OUT"	"Y0"	""	""	""
"5"	""	"LD"	"SM400"	""	""	""
"6"	""	"INC"	"D1"	""	""	""
"8"	""	"P10"	""	""	""	""
"9"	""	"LD"	"SM400"	""	""	""
"10"	""	"INC"	"D2"	""	""	""
"12"	""	"END"	""	""	""	""
)~"},
    {"8.7", "Subroutine call",
     R"~(LD X0
CALL P0
LD SM400
OUT Y1
FEND
P0
LD SM400
INC D0
RET
END
)~",
     R"~("0"	""	"LD"	"X0"	""	""	""
"1"	""	"CALL"	"P0"	""	""	""
"3"	""	"LD"	"SM400"	""	""	""
"4"	""	"OUT"	"Y1"	""	""	""
"5"	""	"FEND"	""	""	""	""
"6"	""	"P0"	""	""	""	""
"7"	""	"LD"	"SM400"	""	""	""
"8"	""	"INC"	"D0"	""	""	""
"10"	""	"RET"	""	""	""	""
"11"	""	"END"	""	""	""	""
)~"},
    {"8.8", "32-bit move and addition overflow",
     R"~(LD SM402
DMOV K2147483647 D0
LD SM400
D+ K1 D0
DMOV D0 D10
D+ K100000 K200000 D20
END
)~",
     R"~("0"	""	"LD"	"SM402"	""	""	""
"1"	""	"DMOV"	"K2147483647"	""	""	""
""	""	""	"D0"	""	""	""
"4"	""	"LD"	"SM400"	""	""	""
"5"	""	"D+"	"K1"	""	""	""
""	""	""	"D0"	""	""	""
"8"	""	"DMOV"	"D0"	""	""	""
""	""	""	"D10"	""	""	""
"11"	""	"D+"	"K100000"	""	""	""
""	""	""	"K200000"	""	""	""
""	""	""	"D20"	""	""	""
"15"	""	"END"	""	""	""	""
)~"},
    {"8.9", "Division with remainder, multiplication, BCD",
     R"~(LD SM400
/ K36 K-5 D0
/ K-36 K5 D2
* K300 K400 D4
D/ K100000 K7 D6
BCD K1234 D20
BIN H0987 D21
DBCD K12345678 D22
END
)~",
     R"~("0"	""	"LD"	"SM400"	""	""	""
"1"	""	"/"	"K36"	""	""	""
""	""	""	"K-5"	""	""	""
""	""	""	"D0"	""	""	""
"5"	""	"/"	"K-36"	""	""	""
""	""	""	"K5"	""	""	""
""	""	""	"D2"	""	""	""
"9"	""	"*"	"K300"	""	""	""
""	""	""	"K400"	""	""	""
""	""	""	"D4"	""	""	""
"13"	""	"D/"	"K100000"	""	""	""
""	""	""	"K7"	""	""	""
""	""	""	"D6"	""	""	""
"17"	""	"BCD"	"K1234"	""	""	""
""	""	""	"D20"	""	""	""
"20"	""	"BIN"	"H0987"	""	""	""
""	""	""	"D21"	""	""	""
"23"	""	"DBCD"	"K12345678"	""	""	""
""	""	""	"D22"	""	""	""
"26"	""	"END"	""	""	""	""
)~"},
    {"8.10", "Digit designation",
     R"~(LD SM400
MOV H1234 K4M0
MOV K4M0 D0
MOV K1M4 D1
MOV K15 K1Y0
MOV HFFFF K2M20
DMOV K8M0 D2
END
)~",
     R"~("0"	""	"LD"	"SM400"	""	""	""
"1"	""	"MOV"	"H1234"	""	""	""
""	""	""	"K4M0"	""	""	""
"4"	""	"MOV"	"K4M0"	""	""	""
""	""	""	"D0"	""	""	""
"7"	""	"MOV"	"K1M4"	""	""	""
""	""	""	"D1"	""	""	""
"10"	""	"MOV"	"K15"	""	""	""
""	""	""	"K1Y0"	""	""	""
"13"	""	"MOV"	"HFFFF"	""	""	""
""	""	""	"K2M20"	""	""	""
"16"	""	"DMOV"	"K8M0"	""	""	""
""	""	""	"D2"	""	""	""
"19"	""	"END"	""	""	""	""
)~"},
    {"8.11", "Index modification",
     R"~(LD SM400
MOV K3 Z0
MOV K100 D10Z0
MOV D10Z0 D20
MOV K10Z0 D21
MOV K5 Z1
MOV K1 K4M0Z1
BMOV D10Z0 D30 K2
END
)~",
     R"~("0"	""	"LD"	"SM400"	""	""	""
"1"	""	"MOV"	"K3"	""	""	""
""	""	""	"Z0"	""	""	""
"4"	""	"MOV"	"K100"	""	""	""
""	""	""	"D10Z0"	""	""	""
"7"	""	"MOV"	"D10Z0"	""	""	""
""	""	""	"D20"	""	""	""
"10"	""	"MOV"	"K10Z0"	""	""	""
""	""	""	"D21"	""	""	""
"13"	""	"MOV"	"K5"	""	""	""
""	""	""	"Z1"	""	""	""
"16"	""	"MOV"	"K1"	""	""	""
""	""	""	"K4M0Z1"	""	""	""
"19"	""	"BMOV"	"D10Z0"	""	""	""
""	""	""	"D30"	""	""	""
""	""	""	"K2"	""	""	""
"23"	""	"END"	""	""	""	""
)~"},
    {"8.12", "Operation error: division by zero",
     R"~(LD SM400
MOV K0 D1
/ K100 D1 D2
MOV K1 D10
OUT Y0
END
)~",
     R"~("0"	""	"LD"	"SM400"	""	""	""
"1"	""	"MOV"	"K0"	""	""	""
""	""	""	"D1"	""	""	""
"4"	""	"/"	"K100"	""	""	""
""	""	""	"D1"	""	""	""
""	""	""	"D2"	""	""	""
"8"	""	"MOV"	"K1"	""	""	""
""	""	""	"D10"	""	""	""
"11"	""	"OUT"	"Y0"	""	""	""
"12"	""	"END"	""	""	""	""
)~"},
    {"8.13", "Floating point",
     R"~(LD SM400
FLT K10 D0
E+ E2.5 D0 D2
E* D2 E2 D4
E/ D2 E4 D6
INT D4 D8
EMOV E-2.5 D10
INT D10 D12
DFLT K100000 D14
END
)~",
     R"~("0"	""	"LD"	"SM400"	""	""	""
"1"	""	"FLT"	"K10"	""	""	""
""	""	""	"D0"	""	""	""
"4"	""	"E+"	"E2.5"	""	""	""
""	""	""	"D0"	""	""	""
""	""	""	"D2"	""	""	""
"8"	""	"E*"	"D2"	""	""	""
""	""	""	"E2"	""	""	""
""	""	""	"D4"	""	""	""
"12"	""	"E/"	"D2"	""	""	""
""	""	""	"E4"	""	""	""
""	""	""	"D6"	""	""	""
"16"	""	"INT"	"D4"	""	""	""
""	""	""	"D8"	""	""	""
"19"	""	"EMOV"	"E-2.5"	""	""	""
""	""	""	"D10"	""	""	""
"22"	""	"INT"	"D10"	""	""	""
""	""	""	"D12"	""	""	""
"25"	""	"DFLT"	"K100000"	""	""	""
""	""	""	"D14"	""	""	""
"28"	""	"END"	""	""	""	""
)~"},
    {"8.14", "Edges: PLS, FF, LDP/LDF, INCP",
     R"~(LD X0
PLS M0
LD M0
FF Y0
LDP X1
SET Y1
LDF X1
RST Y1
LD X2
INCP D0
END
)~",
     R"~("0"	""	"LD"	"X0"	""	""	""
"1"	""	"PLS"	"M0"	""	""	""
"2"	""	"LD"	"M0"	""	""	""
"3"	""	"FF"	"Y0"	""	""	""
"4"	""	"LDP"	"X1"	""	""	""
"5"	""	"SET"	"Y1"	""	""	""
"6"	""	"LDF"	"X1"	""	""	""
"7"	""	"RST"	"Y1"	""	""	""
"8"	""	"LD"	"X2"	""	""	""
"9"	""	"INCP"	"D0"	""	""	""
"11"	""	"END"	""	""	""	""
)~"},
    {"8.15", "Watchdog on an endless loop (Q26UDEHCPU, text form only)",
     R"~(P0
LD SM400
CJ P0
END
)~",
     R"~()~"},
}};

}  // namespace slmp::program::test
