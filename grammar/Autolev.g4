// Autolev 4.1 grammar for the autolev project (ANTLR 4.13.2).
//
// Written for this project from shared/autolev-reference.md and the public corpus.
// Regenerate the parser with:   python tools/regen_parser.py
//
// Structure: the lexer emits NL at every line end that is not continued with '&';
// the driver (src/autolev/syntax.py) splits the token stream at NL and parses each
// logical line with `statementLine`, so an error never spreads past its line.

grammar Autolev;

options { caseInsensitive = true; }

// ---------------------------------------------------------------------------
// Whole file (used by tests and tools); the driver parses each logical line
// (the tokens between two NL) with `singleLine`.
program       : (statementLine? NL)* statementLine? EOF ;
singleLine    : statementLine? EOF ;

// One logical line: statements separated (and optionally ended) by ';'
statementLine : SEMI* statement (SEMI+ statement)* SEMI* | SEMI+ ;

statement
    : declaration
    | massStatement
    | inertiaStatement
    | inputStatement
    | outputStatement
    | unitsStatement
    | unitSystemStatement
    | codeStatement
    | saveStatement
    | encodeStatement
    | runStatement
    | exitStatement
    | setting
    | assignment
    | expressionStatement
    ;

// ---------------------------------------------------------------------------
// Declarations
declaration   : declKeyword PRIME* declarator (COMMA declarator)* ;

declKeyword   : NEWTONIAN | FRAMES | BODIES | PARTICLES | POINTS | CONSTANTS
              | VARIABLES | MOTIONVARIABLES | SPECIFIED | IMAGINARY ;

// WO{3}RD{2,4}' ; C+ ; D- ; B = 3 ; Y''
declarator    : ID declRange (ID? declRange)* ID? declSign? PRIME* (EQUALS expr)?
              | name declSign? PRIME* (EQUALS expr)?
              ;
declRange     : LBRACE rangeBound (COMMA rangeBound)? RBRACE ;
rangeBound    : INT (COLON INT)? ;
declSign      : PLUS | MINUS ;

massStatement : MASS massItem (COMMA massItem)* ;
massItem      : name EQUALS expr (EQUALS expr)? ;

// INERTIA B, I11, I22, I33 [, I12, I23, I31] ; INERTIA B(A), ... ; INERTIA B_O(A), ...
inertiaStatement : INERTIA name (LPAREN name RPAREN)? (COMMA inertiaValue)+ ;
inertiaValue  : expr (EQUALS expr)? ;

// ---------------------------------------------------------------------------
// Assignments
assignment    : target assignOp expr ;
target        : VECNAME                                    # vectorTarget
              | name PRIME* (LBRACK indexList RBRACK)?     # scalarTarget
              ;
assignOp      : EQUALS | COLONEQ | PLUSEQ | MINUSEQ | STAREQ | SLASHEQ | CARETEQ ;

expressionStatement : expr ;

// ---------------------------------------------------------------------------
// Input, output, units, code generation, session commands
inputStatement  : INPUT inputItem (COMMA inputItem)* COMMA? ;
inputItem       : name PRIME* (LBRACK indexList RBRACK)? EQUALS expr unit? ;

outputStatement : OUTPUT outputItem (COMMA outputItem)* COMMA? ;
outputItem      : expr unit? ;

unitsStatement  : UNITS unitsItem (COMMA unitsItem)* ;
unitsItem       : unitsTarget EQUALS unit ;
unitsTarget     : name PRIME*
                | LBRACK name PRIME* (COMMA name PRIME*)* RBRACK
                ;

unitSystemStatement : UNITSYSTEM name (COMMA name)* ;

// 30 DEG, rad/sec, kg*m^2, N/M/S^2, KG.M^2/S
unit            : unitFactor ((STAR | SLASH | DOT) unitFactor)* ;
unitFactor      : name (CARET MINUS? INT)? ;

codeStatement   : CODE name LPAREN argList? RPAREN sweep? fileName (COMMA name)* ;
sweep           : LBRACK name PRIME* unit? EQUALS expr COMMA expr COMMA expr RBRACK ;

saveStatement   : SAVE fileName ;
encodeStatement : ENCODE expr (COMMA expr)* ;
runStatement    : RUN fileName ;
exitStatement   : EXIT | QUIT ;

// A file name is a run of adjacent tokens (the driver checks adjacency):
// tutor6.c, 7segSprint_raw.f, gait2d_osim/gait2d_osim_FK_raw.c, dir\file.al
fileName        : fileNamePart+ ;
fileNamePart    : name | INT | FLOAT | DOT | SLASH | BACKSLASH | MINUS | COLON ;

// Settings from the known list; the value is checked in the IR
setting         : settingName settingValue? ;
settingName     : AUTOZ | AUTORHS | AUTOEPSILON | AUTOEXPRESS | COMPLEX | DEGREES
                | DIGITS | FACTORING | OVERWRITE | BEEPSOUND | PAUSE ;
settingValue    : name | MINUS? number ;

// ---------------------------------------------------------------------------
// Expressions.  '^' binds tighter than unary minus and is right-associative,
// so -a^2 is -(a^2) and a^-2 is a^(-2).
expr
    : <assoc=right> expr CARET expr           # powerExpr
    | (MINUS | PLUS) expr                     # unaryExpr
    | expr (STAR | SLASH) expr                # mulExpr
    | expr (PLUS | MINUS) expr                # addExpr
    | primary                                 # primaryExpr
    ;

primary
    : number                                          # numberAtom
    | VECNAME                                         # vectorAtom
    | name LPAREN argList? RPAREN                     # callAtom
    | name PRIME* LBRACK indexList RBRACK             # indexAtom
    | name declRange (ID? declRange)* ID? PRIME*      # rangeAtom
    | name PRIME*                                     # nameAtom
    | LBRACK matrixRow (SEMI matrixRow)* RBRACK       # matrixAtom
    | LBRACK RBRACK                                   # emptyMatrixAtom
    | LPAREN expr RPAREN                              # parenAtom
    ;

matrixRow       : expr (COMMA expr)* ;
indexList       : indexItem (COMMA indexItem)* ;
indexItem       : expr (COLON expr)? ;

// f(a, 1:2, x=0, x=0:dx, sin(x)=3)
argList         : arg (COMMA arg)* ;
arg             : expr (COLON expr)? (EQUALS expr (COLON expr)?)? ;

number          : INT | FLOAT ;

// Keywords are reserved only where a statement starts; elsewhere they are names.
name
    : ID
    | NEWTONIAN | FRAMES | BODIES | PARTICLES | POINTS | CONSTANTS | VARIABLES
    | MOTIONVARIABLES | SPECIFIED | IMAGINARY | MASS | INERTIA | INPUT | OUTPUT
    | UNITS | UNITSYSTEM | CODE | SAVE | ENCODE | RUN | EXIT | QUIT
    | AUTOZ | AUTORHS | AUTOEPSILON | AUTOEXPRESS | COMPLEX | DEGREES
    | DIGITS | FACTORING | OVERWRITE | BEEPSOUND | PAUSE
    ;

// ---------------------------------------------------------------------------
// Lexer
NEWTONIAN       : 'newtonian' ;
FRAMES          : 'frame' 's'? ;
BODIES          : 'body' | 'bodies' ;
PARTICLES       : 'particle' 's'? ;
POINTS          : 'point' 's'? ;
CONSTANTS       : 'constant' 's'? ;
VARIABLES       : 'variable' 's'? ;
MOTIONVARIABLES : 'motionvariable' 's'? ;
SPECIFIED       : 'specified' 's'? ;
IMAGINARY       : 'imaginary' ;
MASS            : 'mass' ;
INERTIA         : 'inertia' ;
INPUT           : 'input' 's'? ;
OUTPUT          : 'output' 's'? ;
UNITS           : 'units' ;
UNITSYSTEM      : 'unitsystem' ;
CODE            : 'code' ;
SAVE            : 'save' ;
ENCODE          : 'encode' ;
RUN             : 'run' ;
EXIT            : 'exit' ;
QUIT            : 'quit' ;
AUTOZ           : 'autoz' ;
AUTORHS         : 'autorhs' ;
AUTOEPSILON     : 'autoepsilon' ;
AUTOEXPRESS     : 'autoexpress' ;
COMPLEX         : 'complex' ;
DEGREES         : 'degrees' ;
DIGITS          : 'digits' ;
FACTORING       : 'factoring' ;
OVERWRITE       : 'overwrite' ;
BEEPSOUND       : 'beepsound' ;
PAUSE           : 'pause' ;

// Vectors and dyadics: X>, X>>, P_A_B>, I_B_O>>, 0>, 1>>
VECNAME         : [a-z_] [a-z0-9_]* '>' '>'?
                | [01] '>' '>'?
                ;
ID              : [a-z_] [a-z0-9_]* ;

FLOAT           : DIGITS_ '.' DIGITS_? EXPONENT?
                | '.' DIGITS_ EXPONENT?
                | DIGITS_ EXPONENT
                ;
INT             : DIGITS_ ;
fragment DIGITS_  : [0-9]+ ;
fragment EXPONENT : 'e' [+-]? [0-9]+ ;

COLONEQ         : ':=' ;
PLUSEQ          : '+=' ;
MINUSEQ         : '-=' ;
STAREQ          : '*=' ;
SLASHEQ         : '/=' ;
CARETEQ         : '^=' ;
EQUALS          : '=' ;
PLUS            : '+' ;
MINUS           : '-' ;
STAR            : '*' ;
SLASH           : '/' ;
BACKSLASH       : '\\' ;
CARET           : '^' ;
PRIME           : '\'' ;
LPAREN          : '(' ;
RPAREN          : ')' ;
LBRACK          : '[' ;
RBRACK          : ']' ;
LBRACE          : '{' ;
RBRACE          : '}' ;
COMMA           : ',' ;
SEMI            : ';' ;
COLON           : ':' ;
DOT             : '.' ;

// '&' at the end of a line (comment allowed after it) continues the statement.
CONTINUATION    : '&' [ \t]* ('%' ~[\r\n]*)? ('\r'? '\n' | '\r' | EOF) -> skip ;
COMMENT         : '%' ~[\r\n]* -> skip ;
NL              : '\r'? '\n' | '\r' ;
WS              : [ \t\f\u000B\u001A\u00A0]+ -> skip ;
