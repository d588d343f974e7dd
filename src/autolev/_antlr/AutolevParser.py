# Generated from grammar/Autolev.g4 by ANTLR 4.13.2
# encoding: utf-8
from antlr4 import *
from io import StringIO
import sys
if sys.version_info[1] > 5:
	from typing import TextIO
else:
	from typing.io import TextIO

def serializedATN():
    return [
        4,1,65,628,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,2,21,7,21,2,22,7,22,2,23,7,23,2,24,7,24,2,25,7,25,2,26,7,26,
        2,27,7,27,2,28,7,28,2,29,7,29,2,30,7,30,2,31,7,31,2,32,7,32,2,33,
        7,33,2,34,7,34,2,35,7,35,2,36,7,36,2,37,7,37,2,38,7,38,2,39,7,39,
        2,40,7,40,2,41,7,41,2,42,7,42,2,43,7,43,2,44,7,44,2,45,7,45,2,46,
        7,46,2,47,7,47,1,0,3,0,98,8,0,1,0,5,0,101,8,0,10,0,12,0,104,9,0,
        1,0,3,0,107,8,0,1,0,1,0,1,1,3,1,112,8,1,1,1,1,1,1,2,5,2,117,8,2,
        10,2,12,2,120,9,2,1,2,1,2,4,2,124,8,2,11,2,12,2,125,1,2,5,2,129,
        8,2,10,2,12,2,132,9,2,1,2,5,2,135,8,2,10,2,12,2,138,9,2,1,2,4,2,
        141,8,2,11,2,12,2,142,3,2,145,8,2,1,3,1,3,1,3,1,3,1,3,1,3,1,3,1,
        3,1,3,1,3,1,3,1,3,1,3,1,3,1,3,3,3,162,8,3,1,4,1,4,5,4,166,8,4,10,
        4,12,4,169,9,4,1,4,1,4,1,4,5,4,174,8,4,10,4,12,4,177,9,4,1,5,1,5,
        1,6,1,6,1,6,3,6,184,8,6,1,6,5,6,187,8,6,10,6,12,6,190,9,6,1,6,3,
        6,193,8,6,1,6,3,6,196,8,6,1,6,5,6,199,8,6,10,6,12,6,202,9,6,1,6,
        1,6,3,6,206,8,6,1,6,1,6,3,6,210,8,6,1,6,5,6,213,8,6,10,6,12,6,216,
        9,6,1,6,1,6,3,6,220,8,6,3,6,222,8,6,1,7,1,7,1,7,1,7,3,7,228,8,7,
        1,7,1,7,1,8,1,8,1,8,3,8,235,8,8,1,9,1,9,1,10,1,10,1,10,1,10,5,10,
        243,8,10,10,10,12,10,246,9,10,1,11,1,11,1,11,1,11,1,11,3,11,253,
        8,11,1,12,1,12,1,12,1,12,1,12,1,12,3,12,261,8,12,1,12,1,12,4,12,
        265,8,12,11,12,12,12,266,1,13,1,13,1,13,3,13,272,8,13,1,14,1,14,
        1,14,1,14,1,15,1,15,1,15,5,15,281,8,15,10,15,12,15,284,9,15,1,15,
        1,15,1,15,1,15,3,15,290,8,15,3,15,292,8,15,1,16,1,16,1,17,1,17,1,
        18,1,18,1,18,1,18,5,18,302,8,18,10,18,12,18,305,9,18,1,18,3,18,308,
        8,18,1,19,1,19,5,19,312,8,19,10,19,12,19,315,9,19,1,19,1,19,1,19,
        1,19,3,19,321,8,19,1,19,1,19,1,19,3,19,326,8,19,1,20,1,20,1,20,1,
        20,5,20,332,8,20,10,20,12,20,335,9,20,1,20,3,20,338,8,20,1,21,1,
        21,3,21,342,8,21,1,22,1,22,1,22,1,22,5,22,348,8,22,10,22,12,22,351,
        9,22,1,23,1,23,1,23,1,23,1,24,1,24,5,24,359,8,24,10,24,12,24,362,
        9,24,1,24,1,24,1,24,5,24,367,8,24,10,24,12,24,370,9,24,1,24,1,24,
        1,24,5,24,375,8,24,10,24,12,24,378,9,24,5,24,380,8,24,10,24,12,24,
        383,9,24,1,24,1,24,3,24,387,8,24,1,25,1,25,1,25,1,25,5,25,393,8,
        25,10,25,12,25,396,9,25,1,26,1,26,1,26,5,26,401,8,26,10,26,12,26,
        404,9,26,1,27,1,27,1,27,3,27,409,8,27,1,27,3,27,412,8,27,1,28,1,
        28,1,28,1,28,3,28,418,8,28,1,28,1,28,3,28,422,8,28,1,28,1,28,1,28,
        5,28,427,8,28,10,28,12,28,430,9,28,1,29,1,29,1,29,5,29,435,8,29,
        10,29,12,29,438,9,29,1,29,3,29,441,8,29,1,29,1,29,1,29,1,29,1,29,
        1,29,1,29,1,29,1,30,1,30,1,30,1,31,1,31,1,31,1,31,5,31,458,8,31,
        10,31,12,31,461,9,31,1,32,1,32,1,32,1,33,1,33,1,34,4,34,469,8,34,
        11,34,12,34,470,1,35,1,35,1,35,1,35,1,35,1,35,1,35,1,35,3,35,481,
        8,35,1,36,1,36,3,36,485,8,36,1,37,1,37,1,38,1,38,3,38,491,8,38,1,
        38,3,38,494,8,38,1,39,1,39,1,39,1,39,3,39,500,8,39,1,39,1,39,1,39,
        1,39,1,39,1,39,1,39,1,39,1,39,5,39,511,8,39,10,39,12,39,514,9,39,
        1,40,1,40,1,40,1,40,1,40,3,40,521,8,40,1,40,1,40,1,40,1,40,5,40,
        527,8,40,10,40,12,40,530,9,40,1,40,1,40,1,40,1,40,1,40,1,40,1,40,
        3,40,539,8,40,1,40,5,40,542,8,40,10,40,12,40,545,9,40,1,40,3,40,
        548,8,40,1,40,5,40,551,8,40,10,40,12,40,554,9,40,1,40,1,40,5,40,
        558,8,40,10,40,12,40,561,9,40,1,40,1,40,1,40,1,40,5,40,567,8,40,
        10,40,12,40,570,9,40,1,40,1,40,1,40,1,40,1,40,1,40,1,40,1,40,3,40,
        580,8,40,1,41,1,41,1,41,5,41,585,8,41,10,41,12,41,588,9,41,1,42,
        1,42,1,42,5,42,593,8,42,10,42,12,42,596,9,42,1,43,1,43,1,43,3,43,
        601,8,43,1,44,1,44,1,44,5,44,606,8,44,10,44,12,44,609,9,44,1,45,
        1,45,1,45,3,45,614,8,45,1,45,1,45,1,45,1,45,3,45,620,8,45,3,45,622,
        8,45,1,46,1,46,1,47,1,47,1,47,0,1,78,48,0,2,4,6,8,10,12,14,16,18,
        20,22,24,26,28,30,32,34,36,38,40,42,44,46,48,50,52,54,56,58,60,62,
        64,66,68,70,72,74,76,78,80,82,84,86,88,90,92,94,0,9,1,0,1,10,1,0,
        45,46,1,0,38,44,2,0,47,48,61,61,1,0,21,22,1,0,23,33,1,0,47,48,1,
        0,36,37,2,0,1,33,35,35,687,0,102,1,0,0,0,2,111,1,0,0,0,4,144,1,0,
        0,0,6,161,1,0,0,0,8,163,1,0,0,0,10,178,1,0,0,0,12,221,1,0,0,0,14,
        223,1,0,0,0,16,231,1,0,0,0,18,236,1,0,0,0,20,238,1,0,0,0,22,247,
        1,0,0,0,24,254,1,0,0,0,26,268,1,0,0,0,28,273,1,0,0,0,30,291,1,0,
        0,0,32,293,1,0,0,0,34,295,1,0,0,0,36,297,1,0,0,0,38,309,1,0,0,0,
        40,327,1,0,0,0,42,339,1,0,0,0,44,343,1,0,0,0,46,352,1,0,0,0,48,386,
        1,0,0,0,50,388,1,0,0,0,52,397,1,0,0,0,54,405,1,0,0,0,56,413,1,0,
        0,0,58,431,1,0,0,0,60,450,1,0,0,0,62,453,1,0,0,0,64,462,1,0,0,0,
        66,465,1,0,0,0,68,468,1,0,0,0,70,480,1,0,0,0,72,482,1,0,0,0,74,486,
        1,0,0,0,76,493,1,0,0,0,78,499,1,0,0,0,80,579,1,0,0,0,82,581,1,0,
        0,0,84,589,1,0,0,0,86,597,1,0,0,0,88,602,1,0,0,0,90,610,1,0,0,0,
        92,623,1,0,0,0,94,625,1,0,0,0,96,98,3,4,2,0,97,96,1,0,0,0,97,98,
        1,0,0,0,98,99,1,0,0,0,99,101,5,64,0,0,100,97,1,0,0,0,101,104,1,0,
        0,0,102,100,1,0,0,0,102,103,1,0,0,0,103,106,1,0,0,0,104,102,1,0,
        0,0,105,107,3,4,2,0,106,105,1,0,0,0,106,107,1,0,0,0,107,108,1,0,
        0,0,108,109,5,0,0,1,109,1,1,0,0,0,110,112,3,4,2,0,111,110,1,0,0,
        0,111,112,1,0,0,0,112,113,1,0,0,0,113,114,5,0,0,1,114,3,1,0,0,0,
        115,117,5,59,0,0,116,115,1,0,0,0,117,120,1,0,0,0,118,116,1,0,0,0,
        118,119,1,0,0,0,119,121,1,0,0,0,120,118,1,0,0,0,121,130,3,6,3,0,
        122,124,5,59,0,0,123,122,1,0,0,0,124,125,1,0,0,0,125,123,1,0,0,0,
        125,126,1,0,0,0,126,127,1,0,0,0,127,129,3,6,3,0,128,123,1,0,0,0,
        129,132,1,0,0,0,130,128,1,0,0,0,130,131,1,0,0,0,131,136,1,0,0,0,
        132,130,1,0,0,0,133,135,5,59,0,0,134,133,1,0,0,0,135,138,1,0,0,0,
        136,134,1,0,0,0,136,137,1,0,0,0,137,145,1,0,0,0,138,136,1,0,0,0,
        139,141,5,59,0,0,140,139,1,0,0,0,141,142,1,0,0,0,142,140,1,0,0,0,
        142,143,1,0,0,0,143,145,1,0,0,0,144,118,1,0,0,0,144,140,1,0,0,0,
        145,5,1,0,0,0,146,162,3,8,4,0,147,162,3,20,10,0,148,162,3,24,12,
        0,149,162,3,36,18,0,150,162,3,40,20,0,151,162,3,44,22,0,152,162,
        3,50,25,0,153,162,3,56,28,0,154,162,3,60,30,0,155,162,3,62,31,0,
        156,162,3,64,32,0,157,162,3,66,33,0,158,162,3,72,36,0,159,162,3,
        28,14,0,160,162,3,34,17,0,161,146,1,0,0,0,161,147,1,0,0,0,161,148,
        1,0,0,0,161,149,1,0,0,0,161,150,1,0,0,0,161,151,1,0,0,0,161,152,
        1,0,0,0,161,153,1,0,0,0,161,154,1,0,0,0,161,155,1,0,0,0,161,156,
        1,0,0,0,161,157,1,0,0,0,161,158,1,0,0,0,161,159,1,0,0,0,161,160,
        1,0,0,0,162,7,1,0,0,0,163,167,3,10,5,0,164,166,5,51,0,0,165,164,
        1,0,0,0,166,169,1,0,0,0,167,165,1,0,0,0,167,168,1,0,0,0,168,170,
        1,0,0,0,169,167,1,0,0,0,170,175,3,12,6,0,171,172,5,58,0,0,172,174,
        3,12,6,0,173,171,1,0,0,0,174,177,1,0,0,0,175,173,1,0,0,0,175,176,
        1,0,0,0,176,9,1,0,0,0,177,175,1,0,0,0,178,179,7,0,0,0,179,11,1,0,
        0,0,180,181,5,35,0,0,181,188,3,14,7,0,182,184,5,35,0,0,183,182,1,
        0,0,0,183,184,1,0,0,0,184,185,1,0,0,0,185,187,3,14,7,0,186,183,1,
        0,0,0,187,190,1,0,0,0,188,186,1,0,0,0,188,189,1,0,0,0,189,192,1,
        0,0,0,190,188,1,0,0,0,191,193,5,35,0,0,192,191,1,0,0,0,192,193,1,
        0,0,0,193,195,1,0,0,0,194,196,3,18,9,0,195,194,1,0,0,0,195,196,1,
        0,0,0,196,200,1,0,0,0,197,199,5,51,0,0,198,197,1,0,0,0,199,202,1,
        0,0,0,200,198,1,0,0,0,200,201,1,0,0,0,201,205,1,0,0,0,202,200,1,
        0,0,0,203,204,5,44,0,0,204,206,3,78,39,0,205,203,1,0,0,0,205,206,
        1,0,0,0,206,222,1,0,0,0,207,209,3,94,47,0,208,210,3,18,9,0,209,208,
        1,0,0,0,209,210,1,0,0,0,210,214,1,0,0,0,211,213,5,51,0,0,212,211,
        1,0,0,0,213,216,1,0,0,0,214,212,1,0,0,0,214,215,1,0,0,0,215,219,
        1,0,0,0,216,214,1,0,0,0,217,218,5,44,0,0,218,220,3,78,39,0,219,217,
        1,0,0,0,219,220,1,0,0,0,220,222,1,0,0,0,221,180,1,0,0,0,221,207,
        1,0,0,0,222,13,1,0,0,0,223,224,5,56,0,0,224,227,3,16,8,0,225,226,
        5,58,0,0,226,228,3,16,8,0,227,225,1,0,0,0,227,228,1,0,0,0,228,229,
        1,0,0,0,229,230,5,57,0,0,230,15,1,0,0,0,231,234,5,37,0,0,232,233,
        5,60,0,0,233,235,5,37,0,0,234,232,1,0,0,0,234,235,1,0,0,0,235,17,
        1,0,0,0,236,237,7,1,0,0,237,19,1,0,0,0,238,239,5,11,0,0,239,244,
        3,22,11,0,240,241,5,58,0,0,241,243,3,22,11,0,242,240,1,0,0,0,243,
        246,1,0,0,0,244,242,1,0,0,0,244,245,1,0,0,0,245,21,1,0,0,0,246,244,
        1,0,0,0,247,248,3,94,47,0,248,249,5,44,0,0,249,252,3,78,39,0,250,
        251,5,44,0,0,251,253,3,78,39,0,252,250,1,0,0,0,252,253,1,0,0,0,253,
        23,1,0,0,0,254,255,5,12,0,0,255,260,3,94,47,0,256,257,5,52,0,0,257,
        258,3,94,47,0,258,259,5,53,0,0,259,261,1,0,0,0,260,256,1,0,0,0,260,
        261,1,0,0,0,261,264,1,0,0,0,262,263,5,58,0,0,263,265,3,26,13,0,264,
        262,1,0,0,0,265,266,1,0,0,0,266,264,1,0,0,0,266,267,1,0,0,0,267,
        25,1,0,0,0,268,271,3,78,39,0,269,270,5,44,0,0,270,272,3,78,39,0,
        271,269,1,0,0,0,271,272,1,0,0,0,272,27,1,0,0,0,273,274,3,30,15,0,
        274,275,3,32,16,0,275,276,3,78,39,0,276,29,1,0,0,0,277,292,5,34,
        0,0,278,282,3,94,47,0,279,281,5,51,0,0,280,279,1,0,0,0,281,284,1,
        0,0,0,282,280,1,0,0,0,282,283,1,0,0,0,283,289,1,0,0,0,284,282,1,
        0,0,0,285,286,5,54,0,0,286,287,3,84,42,0,287,288,5,55,0,0,288,290,
        1,0,0,0,289,285,1,0,0,0,289,290,1,0,0,0,290,292,1,0,0,0,291,277,
        1,0,0,0,291,278,1,0,0,0,292,31,1,0,0,0,293,294,7,2,0,0,294,33,1,
        0,0,0,295,296,3,78,39,0,296,35,1,0,0,0,297,298,5,13,0,0,298,303,
        3,38,19,0,299,300,5,58,0,0,300,302,3,38,19,0,301,299,1,0,0,0,302,
        305,1,0,0,0,303,301,1,0,0,0,303,304,1,0,0,0,304,307,1,0,0,0,305,
        303,1,0,0,0,306,308,5,58,0,0,307,306,1,0,0,0,307,308,1,0,0,0,308,
        37,1,0,0,0,309,313,3,94,47,0,310,312,5,51,0,0,311,310,1,0,0,0,312,
        315,1,0,0,0,313,311,1,0,0,0,313,314,1,0,0,0,314,320,1,0,0,0,315,
        313,1,0,0,0,316,317,5,54,0,0,317,318,3,84,42,0,318,319,5,55,0,0,
        319,321,1,0,0,0,320,316,1,0,0,0,320,321,1,0,0,0,321,322,1,0,0,0,
        322,323,5,44,0,0,323,325,3,78,39,0,324,326,3,52,26,0,325,324,1,0,
        0,0,325,326,1,0,0,0,326,39,1,0,0,0,327,328,5,14,0,0,328,333,3,42,
        21,0,329,330,5,58,0,0,330,332,3,42,21,0,331,329,1,0,0,0,332,335,
        1,0,0,0,333,331,1,0,0,0,333,334,1,0,0,0,334,337,1,0,0,0,335,333,
        1,0,0,0,336,338,5,58,0,0,337,336,1,0,0,0,337,338,1,0,0,0,338,41,
        1,0,0,0,339,341,3,78,39,0,340,342,3,52,26,0,341,340,1,0,0,0,341,
        342,1,0,0,0,342,43,1,0,0,0,343,344,5,15,0,0,344,349,3,46,23,0,345,
        346,5,58,0,0,346,348,3,46,23,0,347,345,1,0,0,0,348,351,1,0,0,0,349,
        347,1,0,0,0,349,350,1,0,0,0,350,45,1,0,0,0,351,349,1,0,0,0,352,353,
        3,48,24,0,353,354,5,44,0,0,354,355,3,52,26,0,355,47,1,0,0,0,356,
        360,3,94,47,0,357,359,5,51,0,0,358,357,1,0,0,0,359,362,1,0,0,0,360,
        358,1,0,0,0,360,361,1,0,0,0,361,387,1,0,0,0,362,360,1,0,0,0,363,
        364,5,54,0,0,364,368,3,94,47,0,365,367,5,51,0,0,366,365,1,0,0,0,
        367,370,1,0,0,0,368,366,1,0,0,0,368,369,1,0,0,0,369,381,1,0,0,0,
        370,368,1,0,0,0,371,372,5,58,0,0,372,376,3,94,47,0,373,375,5,51,
        0,0,374,373,1,0,0,0,375,378,1,0,0,0,376,374,1,0,0,0,376,377,1,0,
        0,0,377,380,1,0,0,0,378,376,1,0,0,0,379,371,1,0,0,0,380,383,1,0,
        0,0,381,379,1,0,0,0,381,382,1,0,0,0,382,384,1,0,0,0,383,381,1,0,
        0,0,384,385,5,55,0,0,385,387,1,0,0,0,386,356,1,0,0,0,386,363,1,0,
        0,0,387,49,1,0,0,0,388,389,5,16,0,0,389,394,3,94,47,0,390,391,5,
        58,0,0,391,393,3,94,47,0,392,390,1,0,0,0,393,396,1,0,0,0,394,392,
        1,0,0,0,394,395,1,0,0,0,395,51,1,0,0,0,396,394,1,0,0,0,397,402,3,
        54,27,0,398,399,7,3,0,0,399,401,3,54,27,0,400,398,1,0,0,0,401,404,
        1,0,0,0,402,400,1,0,0,0,402,403,1,0,0,0,403,53,1,0,0,0,404,402,1,
        0,0,0,405,411,3,94,47,0,406,408,5,50,0,0,407,409,5,46,0,0,408,407,
        1,0,0,0,408,409,1,0,0,0,409,410,1,0,0,0,410,412,5,37,0,0,411,406,
        1,0,0,0,411,412,1,0,0,0,412,55,1,0,0,0,413,414,5,17,0,0,414,415,
        3,94,47,0,415,417,5,52,0,0,416,418,3,88,44,0,417,416,1,0,0,0,417,
        418,1,0,0,0,418,419,1,0,0,0,419,421,5,53,0,0,420,422,3,58,29,0,421,
        420,1,0,0,0,421,422,1,0,0,0,422,423,1,0,0,0,423,428,3,68,34,0,424,
        425,5,58,0,0,425,427,3,94,47,0,426,424,1,0,0,0,427,430,1,0,0,0,428,
        426,1,0,0,0,428,429,1,0,0,0,429,57,1,0,0,0,430,428,1,0,0,0,431,432,
        5,54,0,0,432,436,3,94,47,0,433,435,5,51,0,0,434,433,1,0,0,0,435,
        438,1,0,0,0,436,434,1,0,0,0,436,437,1,0,0,0,437,440,1,0,0,0,438,
        436,1,0,0,0,439,441,3,52,26,0,440,439,1,0,0,0,440,441,1,0,0,0,441,
        442,1,0,0,0,442,443,5,44,0,0,443,444,3,78,39,0,444,445,5,58,0,0,
        445,446,3,78,39,0,446,447,5,58,0,0,447,448,3,78,39,0,448,449,5,55,
        0,0,449,59,1,0,0,0,450,451,5,18,0,0,451,452,3,68,34,0,452,61,1,0,
        0,0,453,454,5,19,0,0,454,459,3,78,39,0,455,456,5,58,0,0,456,458,
        3,78,39,0,457,455,1,0,0,0,458,461,1,0,0,0,459,457,1,0,0,0,459,460,
        1,0,0,0,460,63,1,0,0,0,461,459,1,0,0,0,462,463,5,20,0,0,463,464,
        3,68,34,0,464,65,1,0,0,0,465,466,7,4,0,0,466,67,1,0,0,0,467,469,
        3,70,35,0,468,467,1,0,0,0,469,470,1,0,0,0,470,468,1,0,0,0,470,471,
        1,0,0,0,471,69,1,0,0,0,472,481,3,94,47,0,473,481,5,37,0,0,474,481,
        5,36,0,0,475,481,5,61,0,0,476,481,5,48,0,0,477,481,5,49,0,0,478,
        481,5,46,0,0,479,481,5,60,0,0,480,472,1,0,0,0,480,473,1,0,0,0,480,
        474,1,0,0,0,480,475,1,0,0,0,480,476,1,0,0,0,480,477,1,0,0,0,480,
        478,1,0,0,0,480,479,1,0,0,0,481,71,1,0,0,0,482,484,3,74,37,0,483,
        485,3,76,38,0,484,483,1,0,0,0,484,485,1,0,0,0,485,73,1,0,0,0,486,
        487,7,5,0,0,487,75,1,0,0,0,488,494,3,94,47,0,489,491,5,46,0,0,490,
        489,1,0,0,0,490,491,1,0,0,0,491,492,1,0,0,0,492,494,3,92,46,0,493,
        488,1,0,0,0,493,490,1,0,0,0,494,77,1,0,0,0,495,496,6,39,-1,0,496,
        497,7,1,0,0,497,500,3,78,39,4,498,500,3,80,40,0,499,495,1,0,0,0,
        499,498,1,0,0,0,500,512,1,0,0,0,501,502,10,5,0,0,502,503,5,50,0,
        0,503,511,3,78,39,5,504,505,10,3,0,0,505,506,7,6,0,0,506,511,3,78,
        39,4,507,508,10,2,0,0,508,509,7,1,0,0,509,511,3,78,39,3,510,501,
        1,0,0,0,510,504,1,0,0,0,510,507,1,0,0,0,511,514,1,0,0,0,512,510,
        1,0,0,0,512,513,1,0,0,0,513,79,1,0,0,0,514,512,1,0,0,0,515,580,3,
        92,46,0,516,580,5,34,0,0,517,518,3,94,47,0,518,520,5,52,0,0,519,
        521,3,88,44,0,520,519,1,0,0,0,520,521,1,0,0,0,521,522,1,0,0,0,522,
        523,5,53,0,0,523,580,1,0,0,0,524,528,3,94,47,0,525,527,5,51,0,0,
        526,525,1,0,0,0,527,530,1,0,0,0,528,526,1,0,0,0,528,529,1,0,0,0,
        529,531,1,0,0,0,530,528,1,0,0,0,531,532,5,54,0,0,532,533,3,84,42,
        0,533,534,5,55,0,0,534,580,1,0,0,0,535,536,3,94,47,0,536,543,3,14,
        7,0,537,539,5,35,0,0,538,537,1,0,0,0,538,539,1,0,0,0,539,540,1,0,
        0,0,540,542,3,14,7,0,541,538,1,0,0,0,542,545,1,0,0,0,543,541,1,0,
        0,0,543,544,1,0,0,0,544,547,1,0,0,0,545,543,1,0,0,0,546,548,5,35,
        0,0,547,546,1,0,0,0,547,548,1,0,0,0,548,552,1,0,0,0,549,551,5,51,
        0,0,550,549,1,0,0,0,551,554,1,0,0,0,552,550,1,0,0,0,552,553,1,0,
        0,0,553,580,1,0,0,0,554,552,1,0,0,0,555,559,3,94,47,0,556,558,5,
        51,0,0,557,556,1,0,0,0,558,561,1,0,0,0,559,557,1,0,0,0,559,560,1,
        0,0,0,560,580,1,0,0,0,561,559,1,0,0,0,562,563,5,54,0,0,563,568,3,
        82,41,0,564,565,5,59,0,0,565,567,3,82,41,0,566,564,1,0,0,0,567,570,
        1,0,0,0,568,566,1,0,0,0,568,569,1,0,0,0,569,571,1,0,0,0,570,568,
        1,0,0,0,571,572,5,55,0,0,572,580,1,0,0,0,573,574,5,54,0,0,574,580,
        5,55,0,0,575,576,5,52,0,0,576,577,3,78,39,0,577,578,5,53,0,0,578,
        580,1,0,0,0,579,515,1,0,0,0,579,516,1,0,0,0,579,517,1,0,0,0,579,
        524,1,0,0,0,579,535,1,0,0,0,579,555,1,0,0,0,579,562,1,0,0,0,579,
        573,1,0,0,0,579,575,1,0,0,0,580,81,1,0,0,0,581,586,3,78,39,0,582,
        583,5,58,0,0,583,585,3,78,39,0,584,582,1,0,0,0,585,588,1,0,0,0,586,
        584,1,0,0,0,586,587,1,0,0,0,587,83,1,0,0,0,588,586,1,0,0,0,589,594,
        3,86,43,0,590,591,5,58,0,0,591,593,3,86,43,0,592,590,1,0,0,0,593,
        596,1,0,0,0,594,592,1,0,0,0,594,595,1,0,0,0,595,85,1,0,0,0,596,594,
        1,0,0,0,597,600,3,78,39,0,598,599,5,60,0,0,599,601,3,78,39,0,600,
        598,1,0,0,0,600,601,1,0,0,0,601,87,1,0,0,0,602,607,3,90,45,0,603,
        604,5,58,0,0,604,606,3,90,45,0,605,603,1,0,0,0,606,609,1,0,0,0,607,
        605,1,0,0,0,607,608,1,0,0,0,608,89,1,0,0,0,609,607,1,0,0,0,610,613,
        3,78,39,0,611,612,5,60,0,0,612,614,3,78,39,0,613,611,1,0,0,0,613,
        614,1,0,0,0,614,621,1,0,0,0,615,616,5,44,0,0,616,619,3,78,39,0,617,
        618,5,60,0,0,618,620,3,78,39,0,619,617,1,0,0,0,619,620,1,0,0,0,620,
        622,1,0,0,0,621,615,1,0,0,0,621,622,1,0,0,0,622,91,1,0,0,0,623,624,
        7,7,0,0,624,93,1,0,0,0,625,626,7,8,0,0,626,95,1,0,0,0,81,97,102,
        106,111,118,125,130,136,142,144,161,167,175,183,188,192,195,200,
        205,209,214,219,221,227,234,244,252,260,266,271,282,289,291,303,
        307,313,320,325,333,337,341,349,360,368,376,381,386,394,402,408,
        411,417,421,428,436,440,459,470,480,484,490,493,499,510,512,520,
        528,538,543,547,552,559,568,579,586,594,600,607,613,619,621
    ]

class AutolevParser ( Parser ):

    grammarFileName = "Autolev.g4"

    atn = ATNDeserializer().deserialize(serializedATN())

    decisionsToDFA = [ DFA(ds, i) for i, ds in enumerate(atn.decisionToState) ]

    sharedContextCache = PredictionContextCache()

    literalNames = [ "<INVALID>", "'newtonian'", "<INVALID>", "<INVALID>", 
                     "<INVALID>", "<INVALID>", "<INVALID>", "<INVALID>", 
                     "<INVALID>", "<INVALID>", "'imaginary'", "'mass'", 
                     "'inertia'", "<INVALID>", "<INVALID>", "'units'", "'unitsystem'", 
                     "'code'", "'save'", "'encode'", "'run'", "'exit'", 
                     "'quit'", "'autoz'", "'autorhs'", "'autoepsilon'", 
                     "'autoexpress'", "'complex'", "'degrees'", "'digits'", 
                     "'factoring'", "'overwrite'", "'beepsound'", "'pause'", 
                     "<INVALID>", "<INVALID>", "<INVALID>", "<INVALID>", 
                     "':='", "'+='", "'-='", "'*='", "'/='", "'^='", "'='", 
                     "'+'", "'-'", "'*'", "'/'", "'\\'", "'^'", "'''", "'('", 
                     "')'", "'['", "']'", "'{'", "'}'", "','", "';'", "':'", 
                     "'.'" ]

    symbolicNames = [ "<INVALID>", "NEWTONIAN", "FRAMES", "BODIES", "PARTICLES", 
                      "POINTS", "CONSTANTS", "VARIABLES", "MOTIONVARIABLES", 
                      "SPECIFIED", "IMAGINARY", "MASS", "INERTIA", "INPUT", 
                      "OUTPUT", "UNITS", "UNITSYSTEM", "CODE", "SAVE", "ENCODE", 
                      "RUN", "EXIT", "QUIT", "AUTOZ", "AUTORHS", "AUTOEPSILON", 
                      "AUTOEXPRESS", "COMPLEX", "DEGREES", "DIGITS", "FACTORING", 
                      "OVERWRITE", "BEEPSOUND", "PAUSE", "VECNAME", "ID", 
                      "FLOAT", "INT", "COLONEQ", "PLUSEQ", "MINUSEQ", "STAREQ", 
                      "SLASHEQ", "CARETEQ", "EQUALS", "PLUS", "MINUS", "STAR", 
                      "SLASH", "BACKSLASH", "CARET", "PRIME", "LPAREN", 
                      "RPAREN", "LBRACK", "RBRACK", "LBRACE", "RBRACE", 
                      "COMMA", "SEMI", "COLON", "DOT", "CONTINUATION", "COMMENT", 
                      "NL", "WS" ]

    RULE_program = 0
    RULE_singleLine = 1
    RULE_statementLine = 2
    RULE_statement = 3
    RULE_declaration = 4
    RULE_declKeyword = 5
    RULE_declarator = 6
    RULE_declRange = 7
    RULE_rangeBound = 8
    RULE_declSign = 9
    RULE_massStatement = 10
    RULE_massItem = 11
    RULE_inertiaStatement = 12
    RULE_inertiaValue = 13
    RULE_assignment = 14
    RULE_target = 15
    RULE_assignOp = 16
    RULE_expressionStatement = 17
    RULE_inputStatement = 18
    RULE_inputItem = 19
    RULE_outputStatement = 20
    RULE_outputItem = 21
    RULE_unitsStatement = 22
    RULE_unitsItem = 23
    RULE_unitsTarget = 24
    RULE_unitSystemStatement = 25
    RULE_unit = 26
    RULE_unitFactor = 27
    RULE_codeStatement = 28
    RULE_sweep = 29
    RULE_saveStatement = 30
    RULE_encodeStatement = 31
    RULE_runStatement = 32
    RULE_exitStatement = 33
    RULE_fileName = 34
    RULE_fileNamePart = 35
    RULE_setting = 36
    RULE_settingName = 37
    RULE_settingValue = 38
    RULE_expr = 39
    RULE_primary = 40
    RULE_matrixRow = 41
    RULE_indexList = 42
    RULE_indexItem = 43
    RULE_argList = 44
    RULE_arg = 45
    RULE_number = 46
    RULE_name = 47

    ruleNames =  [ "program", "singleLine", "statementLine", "statement", 
                   "declaration", "declKeyword", "declarator", "declRange", 
                   "rangeBound", "declSign", "massStatement", "massItem", 
                   "inertiaStatement", "inertiaValue", "assignment", "target", 
                   "assignOp", "expressionStatement", "inputStatement", 
                   "inputItem", "outputStatement", "outputItem", "unitsStatement", 
                   "unitsItem", "unitsTarget", "unitSystemStatement", "unit", 
                   "unitFactor", "codeStatement", "sweep", "saveStatement", 
                   "encodeStatement", "runStatement", "exitStatement", "fileName", 
                   "fileNamePart", "setting", "settingName", "settingValue", 
                   "expr", "primary", "matrixRow", "indexList", "indexItem", 
                   "argList", "arg", "number", "name" ]

    EOF = Token.EOF
    NEWTONIAN=1
    FRAMES=2
    BODIES=3
    PARTICLES=4
    POINTS=5
    CONSTANTS=6
    VARIABLES=7
    MOTIONVARIABLES=8
    SPECIFIED=9
    IMAGINARY=10
    MASS=11
    INERTIA=12
    INPUT=13
    OUTPUT=14
    UNITS=15
    UNITSYSTEM=16
    CODE=17
    SAVE=18
    ENCODE=19
    RUN=20
    EXIT=21
    QUIT=22
    AUTOZ=23
    AUTORHS=24
    AUTOEPSILON=25
    AUTOEXPRESS=26
    COMPLEX=27
    DEGREES=28
    DIGITS=29
    FACTORING=30
    OVERWRITE=31
    BEEPSOUND=32
    PAUSE=33
    VECNAME=34
    ID=35
    FLOAT=36
    INT=37
    COLONEQ=38
    PLUSEQ=39
    MINUSEQ=40
    STAREQ=41
    SLASHEQ=42
    CARETEQ=43
    EQUALS=44
    PLUS=45
    MINUS=46
    STAR=47
    SLASH=48
    BACKSLASH=49
    CARET=50
    PRIME=51
    LPAREN=52
    RPAREN=53
    LBRACK=54
    RBRACK=55
    LBRACE=56
    RBRACE=57
    COMMA=58
    SEMI=59
    COLON=60
    DOT=61
    CONTINUATION=62
    COMMENT=63
    NL=64
    WS=65

    def __init__(self, input:TokenStream, output:TextIO = sys.stdout):
        super().__init__(input, output)
        self.checkVersion("4.13.2")
        self._interp = ParserATNSimulator(self, self.atn, self.decisionsToDFA, self.sharedContextCache)
        self._predicates = None




    class ProgramContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EOF(self):
            return self.getToken(AutolevParser.EOF, 0)

        def NL(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.NL)
            else:
                return self.getToken(AutolevParser.NL, i)

        def statementLine(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.StatementLineContext)
            else:
                return self.getTypedRuleContext(AutolevParser.StatementLineContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_program

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterProgram" ):
                listener.enterProgram(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitProgram" ):
                listener.exitProgram(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitProgram" ):
                return visitor.visitProgram(self)
            else:
                return visitor.visitChildren(self)




    def program(self):

        localctx = AutolevParser.ProgramContext(self, self._ctx, self.state)
        self.enterRule(localctx, 0, self.RULE_program)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 102
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,1,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 97
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if (((_la) & ~0x3f) == 0 and ((1 << _la) & 599084578434449406) != 0):
                        self.state = 96
                        self.statementLine()


                    self.state = 99
                    self.match(AutolevParser.NL) 
                self.state = 104
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,1,self._ctx)

            self.state = 106
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 599084578434449406) != 0):
                self.state = 105
                self.statementLine()


            self.state = 108
            self.match(AutolevParser.EOF)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SingleLineContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EOF(self):
            return self.getToken(AutolevParser.EOF, 0)

        def statementLine(self):
            return self.getTypedRuleContext(AutolevParser.StatementLineContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_singleLine

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterSingleLine" ):
                listener.enterSingleLine(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitSingleLine" ):
                listener.exitSingleLine(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSingleLine" ):
                return visitor.visitSingleLine(self)
            else:
                return visitor.visitChildren(self)




    def singleLine(self):

        localctx = AutolevParser.SingleLineContext(self, self._ctx, self.state)
        self.enterRule(localctx, 2, self.RULE_singleLine)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 111
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 599084578434449406) != 0):
                self.state = 110
                self.statementLine()


            self.state = 113
            self.match(AutolevParser.EOF)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class StatementLineContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def statement(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.StatementContext)
            else:
                return self.getTypedRuleContext(AutolevParser.StatementContext,i)


        def SEMI(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.SEMI)
            else:
                return self.getToken(AutolevParser.SEMI, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_statementLine

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterStatementLine" ):
                listener.enterStatementLine(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitStatementLine" ):
                listener.exitStatementLine(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitStatementLine" ):
                return visitor.visitStatementLine(self)
            else:
                return visitor.visitChildren(self)




    def statementLine(self):

        localctx = AutolevParser.StatementLineContext(self, self._ctx, self.state)
        self.enterRule(localctx, 4, self.RULE_statementLine)
        self._la = 0 # Token type
        try:
            self.state = 144
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,9,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 118
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==59:
                    self.state = 115
                    self.match(AutolevParser.SEMI)
                    self.state = 120
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 121
                self.statement()
                self.state = 130
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,6,self._ctx)
                while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                    if _alt==1:
                        self.state = 123 
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        while True:
                            self.state = 122
                            self.match(AutolevParser.SEMI)
                            self.state = 125 
                            self._errHandler.sync(self)
                            _la = self._input.LA(1)
                            if not (_la==59):
                                break

                        self.state = 127
                        self.statement() 
                    self.state = 132
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,6,self._ctx)

                self.state = 136
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==59:
                    self.state = 133
                    self.match(AutolevParser.SEMI)
                    self.state = 138
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 140 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while True:
                    self.state = 139
                    self.match(AutolevParser.SEMI)
                    self.state = 142 
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if not (_la==59):
                        break

                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class StatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def declaration(self):
            return self.getTypedRuleContext(AutolevParser.DeclarationContext,0)


        def massStatement(self):
            return self.getTypedRuleContext(AutolevParser.MassStatementContext,0)


        def inertiaStatement(self):
            return self.getTypedRuleContext(AutolevParser.InertiaStatementContext,0)


        def inputStatement(self):
            return self.getTypedRuleContext(AutolevParser.InputStatementContext,0)


        def outputStatement(self):
            return self.getTypedRuleContext(AutolevParser.OutputStatementContext,0)


        def unitsStatement(self):
            return self.getTypedRuleContext(AutolevParser.UnitsStatementContext,0)


        def unitSystemStatement(self):
            return self.getTypedRuleContext(AutolevParser.UnitSystemStatementContext,0)


        def codeStatement(self):
            return self.getTypedRuleContext(AutolevParser.CodeStatementContext,0)


        def saveStatement(self):
            return self.getTypedRuleContext(AutolevParser.SaveStatementContext,0)


        def encodeStatement(self):
            return self.getTypedRuleContext(AutolevParser.EncodeStatementContext,0)


        def runStatement(self):
            return self.getTypedRuleContext(AutolevParser.RunStatementContext,0)


        def exitStatement(self):
            return self.getTypedRuleContext(AutolevParser.ExitStatementContext,0)


        def setting(self):
            return self.getTypedRuleContext(AutolevParser.SettingContext,0)


        def assignment(self):
            return self.getTypedRuleContext(AutolevParser.AssignmentContext,0)


        def expressionStatement(self):
            return self.getTypedRuleContext(AutolevParser.ExpressionStatementContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_statement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterStatement" ):
                listener.enterStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitStatement" ):
                listener.exitStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitStatement" ):
                return visitor.visitStatement(self)
            else:
                return visitor.visitChildren(self)




    def statement(self):

        localctx = AutolevParser.StatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 6, self.RULE_statement)
        try:
            self.state = 161
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,10,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 146
                self.declaration()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 147
                self.massStatement()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 148
                self.inertiaStatement()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 149
                self.inputStatement()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 150
                self.outputStatement()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 151
                self.unitsStatement()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 152
                self.unitSystemStatement()
                pass

            elif la_ == 8:
                self.enterOuterAlt(localctx, 8)
                self.state = 153
                self.codeStatement()
                pass

            elif la_ == 9:
                self.enterOuterAlt(localctx, 9)
                self.state = 154
                self.saveStatement()
                pass

            elif la_ == 10:
                self.enterOuterAlt(localctx, 10)
                self.state = 155
                self.encodeStatement()
                pass

            elif la_ == 11:
                self.enterOuterAlt(localctx, 11)
                self.state = 156
                self.runStatement()
                pass

            elif la_ == 12:
                self.enterOuterAlt(localctx, 12)
                self.state = 157
                self.exitStatement()
                pass

            elif la_ == 13:
                self.enterOuterAlt(localctx, 13)
                self.state = 158
                self.setting()
                pass

            elif la_ == 14:
                self.enterOuterAlt(localctx, 14)
                self.state = 159
                self.assignment()
                pass

            elif la_ == 15:
                self.enterOuterAlt(localctx, 15)
                self.state = 160
                self.expressionStatement()
                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def declKeyword(self):
            return self.getTypedRuleContext(AutolevParser.DeclKeywordContext,0)


        def declarator(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.DeclaratorContext)
            else:
                return self.getTypedRuleContext(AutolevParser.DeclaratorContext,i)


        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_declaration

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterDeclaration" ):
                listener.enterDeclaration(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitDeclaration" ):
                listener.exitDeclaration(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclaration" ):
                return visitor.visitDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def declaration(self):

        localctx = AutolevParser.DeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 8, self.RULE_declaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 163
            self.declKeyword()
            self.state = 167
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==51:
                self.state = 164
                self.match(AutolevParser.PRIME)
                self.state = 169
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 170
            self.declarator()
            self.state = 175
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 171
                self.match(AutolevParser.COMMA)
                self.state = 172
                self.declarator()
                self.state = 177
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclKeywordContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def NEWTONIAN(self):
            return self.getToken(AutolevParser.NEWTONIAN, 0)

        def FRAMES(self):
            return self.getToken(AutolevParser.FRAMES, 0)

        def BODIES(self):
            return self.getToken(AutolevParser.BODIES, 0)

        def PARTICLES(self):
            return self.getToken(AutolevParser.PARTICLES, 0)

        def POINTS(self):
            return self.getToken(AutolevParser.POINTS, 0)

        def CONSTANTS(self):
            return self.getToken(AutolevParser.CONSTANTS, 0)

        def VARIABLES(self):
            return self.getToken(AutolevParser.VARIABLES, 0)

        def MOTIONVARIABLES(self):
            return self.getToken(AutolevParser.MOTIONVARIABLES, 0)

        def SPECIFIED(self):
            return self.getToken(AutolevParser.SPECIFIED, 0)

        def IMAGINARY(self):
            return self.getToken(AutolevParser.IMAGINARY, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_declKeyword

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterDeclKeyword" ):
                listener.enterDeclKeyword(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitDeclKeyword" ):
                listener.exitDeclKeyword(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclKeyword" ):
                return visitor.visitDeclKeyword(self)
            else:
                return visitor.visitChildren(self)




    def declKeyword(self):

        localctx = AutolevParser.DeclKeywordContext(self, self._ctx, self.state)
        self.enterRule(localctx, 10, self.RULE_declKeyword)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 178
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 2046) != 0)):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclaratorContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ID(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.ID)
            else:
                return self.getToken(AutolevParser.ID, i)

        def declRange(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.DeclRangeContext)
            else:
                return self.getTypedRuleContext(AutolevParser.DeclRangeContext,i)


        def declSign(self):
            return self.getTypedRuleContext(AutolevParser.DeclSignContext,0)


        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def EQUALS(self):
            return self.getToken(AutolevParser.EQUALS, 0)

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_declarator

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterDeclarator" ):
                listener.enterDeclarator(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitDeclarator" ):
                listener.exitDeclarator(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclarator" ):
                return visitor.visitDeclarator(self)
            else:
                return visitor.visitChildren(self)




    def declarator(self):

        localctx = AutolevParser.DeclaratorContext(self, self._ctx, self.state)
        self.enterRule(localctx, 12, self.RULE_declarator)
        self._la = 0 # Token type
        try:
            self.state = 221
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,22,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 180
                self.match(AutolevParser.ID)
                self.state = 181
                self.declRange()
                self.state = 188
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,14,self._ctx)
                while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                    if _alt==1:
                        self.state = 183
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if _la==35:
                            self.state = 182
                            self.match(AutolevParser.ID)


                        self.state = 185
                        self.declRange() 
                    self.state = 190
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,14,self._ctx)

                self.state = 192
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==35:
                    self.state = 191
                    self.match(AutolevParser.ID)


                self.state = 195
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==45 or _la==46:
                    self.state = 194
                    self.declSign()


                self.state = 200
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==51:
                    self.state = 197
                    self.match(AutolevParser.PRIME)
                    self.state = 202
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 205
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==44:
                    self.state = 203
                    self.match(AutolevParser.EQUALS)
                    self.state = 204
                    self.expr(0)


                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 207
                self.name()
                self.state = 209
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==45 or _la==46:
                    self.state = 208
                    self.declSign()


                self.state = 214
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==51:
                    self.state = 211
                    self.match(AutolevParser.PRIME)
                    self.state = 216
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 219
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==44:
                    self.state = 217
                    self.match(AutolevParser.EQUALS)
                    self.state = 218
                    self.expr(0)


                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclRangeContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def LBRACE(self):
            return self.getToken(AutolevParser.LBRACE, 0)

        def rangeBound(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.RangeBoundContext)
            else:
                return self.getTypedRuleContext(AutolevParser.RangeBoundContext,i)


        def RBRACE(self):
            return self.getToken(AutolevParser.RBRACE, 0)

        def COMMA(self):
            return self.getToken(AutolevParser.COMMA, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_declRange

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterDeclRange" ):
                listener.enterDeclRange(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitDeclRange" ):
                listener.exitDeclRange(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclRange" ):
                return visitor.visitDeclRange(self)
            else:
                return visitor.visitChildren(self)




    def declRange(self):

        localctx = AutolevParser.DeclRangeContext(self, self._ctx, self.state)
        self.enterRule(localctx, 14, self.RULE_declRange)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 223
            self.match(AutolevParser.LBRACE)
            self.state = 224
            self.rangeBound()
            self.state = 227
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==58:
                self.state = 225
                self.match(AutolevParser.COMMA)
                self.state = 226
                self.rangeBound()


            self.state = 229
            self.match(AutolevParser.RBRACE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class RangeBoundContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def INT(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.INT)
            else:
                return self.getToken(AutolevParser.INT, i)

        def COLON(self):
            return self.getToken(AutolevParser.COLON, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_rangeBound

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterRangeBound" ):
                listener.enterRangeBound(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitRangeBound" ):
                listener.exitRangeBound(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRangeBound" ):
                return visitor.visitRangeBound(self)
            else:
                return visitor.visitChildren(self)




    def rangeBound(self):

        localctx = AutolevParser.RangeBoundContext(self, self._ctx, self.state)
        self.enterRule(localctx, 16, self.RULE_rangeBound)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 231
            self.match(AutolevParser.INT)
            self.state = 234
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==60:
                self.state = 232
                self.match(AutolevParser.COLON)
                self.state = 233
                self.match(AutolevParser.INT)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclSignContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def PLUS(self):
            return self.getToken(AutolevParser.PLUS, 0)

        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_declSign

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterDeclSign" ):
                listener.enterDeclSign(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitDeclSign" ):
                listener.exitDeclSign(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclSign" ):
                return visitor.visitDeclSign(self)
            else:
                return visitor.visitChildren(self)




    def declSign(self):

        localctx = AutolevParser.DeclSignContext(self, self._ctx, self.state)
        self.enterRule(localctx, 18, self.RULE_declSign)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 236
            _la = self._input.LA(1)
            if not(_la==45 or _la==46):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class MassStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def MASS(self):
            return self.getToken(AutolevParser.MASS, 0)

        def massItem(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.MassItemContext)
            else:
                return self.getTypedRuleContext(AutolevParser.MassItemContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_massStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterMassStatement" ):
                listener.enterMassStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitMassStatement" ):
                listener.exitMassStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMassStatement" ):
                return visitor.visitMassStatement(self)
            else:
                return visitor.visitChildren(self)




    def massStatement(self):

        localctx = AutolevParser.MassStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 20, self.RULE_massStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 238
            self.match(AutolevParser.MASS)
            self.state = 239
            self.massItem()
            self.state = 244
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 240
                self.match(AutolevParser.COMMA)
                self.state = 241
                self.massItem()
                self.state = 246
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class MassItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)


        def EQUALS(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.EQUALS)
            else:
                return self.getToken(AutolevParser.EQUALS, i)

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_massItem

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterMassItem" ):
                listener.enterMassItem(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitMassItem" ):
                listener.exitMassItem(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMassItem" ):
                return visitor.visitMassItem(self)
            else:
                return visitor.visitChildren(self)




    def massItem(self):

        localctx = AutolevParser.MassItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 22, self.RULE_massItem)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 247
            self.name()
            self.state = 248
            self.match(AutolevParser.EQUALS)
            self.state = 249
            self.expr(0)
            self.state = 252
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==44:
                self.state = 250
                self.match(AutolevParser.EQUALS)
                self.state = 251
                self.expr(0)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InertiaStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def INERTIA(self):
            return self.getToken(AutolevParser.INERTIA, 0)

        def name(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.NameContext)
            else:
                return self.getTypedRuleContext(AutolevParser.NameContext,i)


        def LPAREN(self):
            return self.getToken(AutolevParser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(AutolevParser.RPAREN, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def inertiaValue(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.InertiaValueContext)
            else:
                return self.getTypedRuleContext(AutolevParser.InertiaValueContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_inertiaStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterInertiaStatement" ):
                listener.enterInertiaStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitInertiaStatement" ):
                listener.exitInertiaStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInertiaStatement" ):
                return visitor.visitInertiaStatement(self)
            else:
                return visitor.visitChildren(self)




    def inertiaStatement(self):

        localctx = AutolevParser.InertiaStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 24, self.RULE_inertiaStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 254
            self.match(AutolevParser.INERTIA)
            self.state = 255
            self.name()
            self.state = 260
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==52:
                self.state = 256
                self.match(AutolevParser.LPAREN)
                self.state = 257
                self.name()
                self.state = 258
                self.match(AutolevParser.RPAREN)


            self.state = 264 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 262
                self.match(AutolevParser.COMMA)
                self.state = 263
                self.inertiaValue()
                self.state = 266 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not (_la==58):
                    break

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InertiaValueContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def EQUALS(self):
            return self.getToken(AutolevParser.EQUALS, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_inertiaValue

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterInertiaValue" ):
                listener.enterInertiaValue(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitInertiaValue" ):
                listener.exitInertiaValue(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInertiaValue" ):
                return visitor.visitInertiaValue(self)
            else:
                return visitor.visitChildren(self)




    def inertiaValue(self):

        localctx = AutolevParser.InertiaValueContext(self, self._ctx, self.state)
        self.enterRule(localctx, 26, self.RULE_inertiaValue)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 268
            self.expr(0)
            self.state = 271
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==44:
                self.state = 269
                self.match(AutolevParser.EQUALS)
                self.state = 270
                self.expr(0)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class AssignmentContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def target(self):
            return self.getTypedRuleContext(AutolevParser.TargetContext,0)


        def assignOp(self):
            return self.getTypedRuleContext(AutolevParser.AssignOpContext,0)


        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_assignment

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterAssignment" ):
                listener.enterAssignment(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitAssignment" ):
                listener.exitAssignment(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitAssignment" ):
                return visitor.visitAssignment(self)
            else:
                return visitor.visitChildren(self)




    def assignment(self):

        localctx = AutolevParser.AssignmentContext(self, self._ctx, self.state)
        self.enterRule(localctx, 28, self.RULE_assignment)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 273
            self.target()
            self.state = 274
            self.assignOp()
            self.state = 275
            self.expr(0)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class TargetContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return AutolevParser.RULE_target

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class ScalarTargetContext(TargetContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.TargetContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)

        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)
        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def indexList(self):
            return self.getTypedRuleContext(AutolevParser.IndexListContext,0)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterScalarTarget" ):
                listener.enterScalarTarget(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitScalarTarget" ):
                listener.exitScalarTarget(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitScalarTarget" ):
                return visitor.visitScalarTarget(self)
            else:
                return visitor.visitChildren(self)


    class VectorTargetContext(TargetContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.TargetContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def VECNAME(self):
            return self.getToken(AutolevParser.VECNAME, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterVectorTarget" ):
                listener.enterVectorTarget(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitVectorTarget" ):
                listener.exitVectorTarget(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitVectorTarget" ):
                return visitor.visitVectorTarget(self)
            else:
                return visitor.visitChildren(self)



    def target(self):

        localctx = AutolevParser.TargetContext(self, self._ctx, self.state)
        self.enterRule(localctx, 30, self.RULE_target)
        self._la = 0 # Token type
        try:
            self.state = 291
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [34]:
                localctx = AutolevParser.VectorTargetContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 277
                self.match(AutolevParser.VECNAME)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 35]:
                localctx = AutolevParser.ScalarTargetContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 278
                self.name()
                self.state = 282
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==51:
                    self.state = 279
                    self.match(AutolevParser.PRIME)
                    self.state = 284
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 289
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==54:
                    self.state = 285
                    self.match(AutolevParser.LBRACK)
                    self.state = 286
                    self.indexList()
                    self.state = 287
                    self.match(AutolevParser.RBRACK)


                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class AssignOpContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EQUALS(self):
            return self.getToken(AutolevParser.EQUALS, 0)

        def COLONEQ(self):
            return self.getToken(AutolevParser.COLONEQ, 0)

        def PLUSEQ(self):
            return self.getToken(AutolevParser.PLUSEQ, 0)

        def MINUSEQ(self):
            return self.getToken(AutolevParser.MINUSEQ, 0)

        def STAREQ(self):
            return self.getToken(AutolevParser.STAREQ, 0)

        def SLASHEQ(self):
            return self.getToken(AutolevParser.SLASHEQ, 0)

        def CARETEQ(self):
            return self.getToken(AutolevParser.CARETEQ, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_assignOp

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterAssignOp" ):
                listener.enterAssignOp(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitAssignOp" ):
                listener.exitAssignOp(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitAssignOp" ):
                return visitor.visitAssignOp(self)
            else:
                return visitor.visitChildren(self)




    def assignOp(self):

        localctx = AutolevParser.AssignOpContext(self, self._ctx, self.state)
        self.enterRule(localctx, 32, self.RULE_assignOp)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 293
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 34909494181888) != 0)):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExpressionStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_expressionStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterExpressionStatement" ):
                listener.enterExpressionStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitExpressionStatement" ):
                listener.exitExpressionStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExpressionStatement" ):
                return visitor.visitExpressionStatement(self)
            else:
                return visitor.visitChildren(self)




    def expressionStatement(self):

        localctx = AutolevParser.ExpressionStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 34, self.RULE_expressionStatement)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 295
            self.expr(0)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InputStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def INPUT(self):
            return self.getToken(AutolevParser.INPUT, 0)

        def inputItem(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.InputItemContext)
            else:
                return self.getTypedRuleContext(AutolevParser.InputItemContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_inputStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterInputStatement" ):
                listener.enterInputStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitInputStatement" ):
                listener.exitInputStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInputStatement" ):
                return visitor.visitInputStatement(self)
            else:
                return visitor.visitChildren(self)




    def inputStatement(self):

        localctx = AutolevParser.InputStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 36, self.RULE_inputStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 297
            self.match(AutolevParser.INPUT)
            self.state = 298
            self.inputItem()
            self.state = 303
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,33,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 299
                    self.match(AutolevParser.COMMA)
                    self.state = 300
                    self.inputItem() 
                self.state = 305
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,33,self._ctx)

            self.state = 307
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==58:
                self.state = 306
                self.match(AutolevParser.COMMA)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InputItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)


        def EQUALS(self):
            return self.getToken(AutolevParser.EQUALS, 0)

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)

        def indexList(self):
            return self.getTypedRuleContext(AutolevParser.IndexListContext,0)


        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def unit(self):
            return self.getTypedRuleContext(AutolevParser.UnitContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_inputItem

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterInputItem" ):
                listener.enterInputItem(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitInputItem" ):
                listener.exitInputItem(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInputItem" ):
                return visitor.visitInputItem(self)
            else:
                return visitor.visitChildren(self)




    def inputItem(self):

        localctx = AutolevParser.InputItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 38, self.RULE_inputItem)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 309
            self.name()
            self.state = 313
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==51:
                self.state = 310
                self.match(AutolevParser.PRIME)
                self.state = 315
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 320
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==54:
                self.state = 316
                self.match(AutolevParser.LBRACK)
                self.state = 317
                self.indexList()
                self.state = 318
                self.match(AutolevParser.RBRACK)


            self.state = 322
            self.match(AutolevParser.EQUALS)
            self.state = 323
            self.expr(0)
            self.state = 325
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 51539607550) != 0):
                self.state = 324
                self.unit()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class OutputStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def OUTPUT(self):
            return self.getToken(AutolevParser.OUTPUT, 0)

        def outputItem(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.OutputItemContext)
            else:
                return self.getTypedRuleContext(AutolevParser.OutputItemContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_outputStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterOutputStatement" ):
                listener.enterOutputStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitOutputStatement" ):
                listener.exitOutputStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitOutputStatement" ):
                return visitor.visitOutputStatement(self)
            else:
                return visitor.visitChildren(self)




    def outputStatement(self):

        localctx = AutolevParser.OutputStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 40, self.RULE_outputStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 327
            self.match(AutolevParser.OUTPUT)
            self.state = 328
            self.outputItem()
            self.state = 333
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,38,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 329
                    self.match(AutolevParser.COMMA)
                    self.state = 330
                    self.outputItem() 
                self.state = 335
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,38,self._ctx)

            self.state = 337
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==58:
                self.state = 336
                self.match(AutolevParser.COMMA)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class OutputItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def unit(self):
            return self.getTypedRuleContext(AutolevParser.UnitContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_outputItem

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterOutputItem" ):
                listener.enterOutputItem(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitOutputItem" ):
                listener.exitOutputItem(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitOutputItem" ):
                return visitor.visitOutputItem(self)
            else:
                return visitor.visitChildren(self)




    def outputItem(self):

        localctx = AutolevParser.OutputItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 42, self.RULE_outputItem)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 339
            self.expr(0)
            self.state = 341
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 51539607550) != 0):
                self.state = 340
                self.unit()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitsStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def UNITS(self):
            return self.getToken(AutolevParser.UNITS, 0)

        def unitsItem(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.UnitsItemContext)
            else:
                return self.getTypedRuleContext(AutolevParser.UnitsItemContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_unitsStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterUnitsStatement" ):
                listener.enterUnitsStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitUnitsStatement" ):
                listener.exitUnitsStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitsStatement" ):
                return visitor.visitUnitsStatement(self)
            else:
                return visitor.visitChildren(self)




    def unitsStatement(self):

        localctx = AutolevParser.UnitsStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 44, self.RULE_unitsStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 343
            self.match(AutolevParser.UNITS)
            self.state = 344
            self.unitsItem()
            self.state = 349
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 345
                self.match(AutolevParser.COMMA)
                self.state = 346
                self.unitsItem()
                self.state = 351
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitsItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def unitsTarget(self):
            return self.getTypedRuleContext(AutolevParser.UnitsTargetContext,0)


        def EQUALS(self):
            return self.getToken(AutolevParser.EQUALS, 0)

        def unit(self):
            return self.getTypedRuleContext(AutolevParser.UnitContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_unitsItem

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterUnitsItem" ):
                listener.enterUnitsItem(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitUnitsItem" ):
                listener.exitUnitsItem(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitsItem" ):
                return visitor.visitUnitsItem(self)
            else:
                return visitor.visitChildren(self)




    def unitsItem(self):

        localctx = AutolevParser.UnitsItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 46, self.RULE_unitsItem)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 352
            self.unitsTarget()
            self.state = 353
            self.match(AutolevParser.EQUALS)
            self.state = 354
            self.unit()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitsTargetContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def name(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.NameContext)
            else:
                return self.getTypedRuleContext(AutolevParser.NameContext,i)


        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_unitsTarget

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterUnitsTarget" ):
                listener.enterUnitsTarget(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitUnitsTarget" ):
                listener.exitUnitsTarget(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitsTarget" ):
                return visitor.visitUnitsTarget(self)
            else:
                return visitor.visitChildren(self)




    def unitsTarget(self):

        localctx = AutolevParser.UnitsTargetContext(self, self._ctx, self.state)
        self.enterRule(localctx, 48, self.RULE_unitsTarget)
        self._la = 0 # Token type
        try:
            self.state = 386
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 35]:
                self.enterOuterAlt(localctx, 1)
                self.state = 356
                self.name()
                self.state = 360
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==51:
                    self.state = 357
                    self.match(AutolevParser.PRIME)
                    self.state = 362
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass
            elif token in [54]:
                self.enterOuterAlt(localctx, 2)
                self.state = 363
                self.match(AutolevParser.LBRACK)
                self.state = 364
                self.name()
                self.state = 368
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==51:
                    self.state = 365
                    self.match(AutolevParser.PRIME)
                    self.state = 370
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 381
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==58:
                    self.state = 371
                    self.match(AutolevParser.COMMA)
                    self.state = 372
                    self.name()
                    self.state = 376
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    while _la==51:
                        self.state = 373
                        self.match(AutolevParser.PRIME)
                        self.state = 378
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)

                    self.state = 383
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 384
                self.match(AutolevParser.RBRACK)
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitSystemStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def UNITSYSTEM(self):
            return self.getToken(AutolevParser.UNITSYSTEM, 0)

        def name(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.NameContext)
            else:
                return self.getTypedRuleContext(AutolevParser.NameContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_unitSystemStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterUnitSystemStatement" ):
                listener.enterUnitSystemStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitUnitSystemStatement" ):
                listener.exitUnitSystemStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitSystemStatement" ):
                return visitor.visitUnitSystemStatement(self)
            else:
                return visitor.visitChildren(self)




    def unitSystemStatement(self):

        localctx = AutolevParser.UnitSystemStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 50, self.RULE_unitSystemStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 388
            self.match(AutolevParser.UNITSYSTEM)
            self.state = 389
            self.name()
            self.state = 394
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 390
                self.match(AutolevParser.COMMA)
                self.state = 391
                self.name()
                self.state = 396
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def unitFactor(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.UnitFactorContext)
            else:
                return self.getTypedRuleContext(AutolevParser.UnitFactorContext,i)


        def STAR(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.STAR)
            else:
                return self.getToken(AutolevParser.STAR, i)

        def SLASH(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.SLASH)
            else:
                return self.getToken(AutolevParser.SLASH, i)

        def DOT(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.DOT)
            else:
                return self.getToken(AutolevParser.DOT, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_unit

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterUnit" ):
                listener.enterUnit(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitUnit" ):
                listener.exitUnit(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnit" ):
                return visitor.visitUnit(self)
            else:
                return visitor.visitChildren(self)




    def unit(self):

        localctx = AutolevParser.UnitContext(self, self._ctx, self.state)
        self.enterRule(localctx, 52, self.RULE_unit)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 397
            self.unitFactor()
            self.state = 402
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while (((_la) & ~0x3f) == 0 and ((1 << _la) & 2306265221678759936) != 0):
                self.state = 398
                _la = self._input.LA(1)
                if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 2306265221678759936) != 0)):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                self.state = 399
                self.unitFactor()
                self.state = 404
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitFactorContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)


        def CARET(self):
            return self.getToken(AutolevParser.CARET, 0)

        def INT(self):
            return self.getToken(AutolevParser.INT, 0)

        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_unitFactor

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterUnitFactor" ):
                listener.enterUnitFactor(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitUnitFactor" ):
                listener.exitUnitFactor(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitFactor" ):
                return visitor.visitUnitFactor(self)
            else:
                return visitor.visitChildren(self)




    def unitFactor(self):

        localctx = AutolevParser.UnitFactorContext(self, self._ctx, self.state)
        self.enterRule(localctx, 54, self.RULE_unitFactor)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 405
            self.name()
            self.state = 411
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==50:
                self.state = 406
                self.match(AutolevParser.CARET)
                self.state = 408
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==46:
                    self.state = 407
                    self.match(AutolevParser.MINUS)


                self.state = 410
                self.match(AutolevParser.INT)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class CodeStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def CODE(self):
            return self.getToken(AutolevParser.CODE, 0)

        def name(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.NameContext)
            else:
                return self.getTypedRuleContext(AutolevParser.NameContext,i)


        def LPAREN(self):
            return self.getToken(AutolevParser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(AutolevParser.RPAREN, 0)

        def fileName(self):
            return self.getTypedRuleContext(AutolevParser.FileNameContext,0)


        def argList(self):
            return self.getTypedRuleContext(AutolevParser.ArgListContext,0)


        def sweep(self):
            return self.getTypedRuleContext(AutolevParser.SweepContext,0)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_codeStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterCodeStatement" ):
                listener.enterCodeStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitCodeStatement" ):
                listener.exitCodeStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitCodeStatement" ):
                return visitor.visitCodeStatement(self)
            else:
                return visitor.visitChildren(self)




    def codeStatement(self):

        localctx = AutolevParser.CodeStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 56, self.RULE_codeStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 413
            self.match(AutolevParser.CODE)
            self.state = 414
            self.name()
            self.state = 415
            self.match(AutolevParser.LPAREN)
            self.state = 417
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 22623826131025918) != 0):
                self.state = 416
                self.argList()


            self.state = 419
            self.match(AutolevParser.RPAREN)
            self.state = 421
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==54:
                self.state = 420
                self.sweep()


            self.state = 423
            self.fileName()
            self.state = 428
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 424
                self.match(AutolevParser.COMMA)
                self.state = 425
                self.name()
                self.state = 430
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SweepContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)


        def EQUALS(self):
            return self.getToken(AutolevParser.EQUALS, 0)

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def unit(self):
            return self.getTypedRuleContext(AutolevParser.UnitContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_sweep

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterSweep" ):
                listener.enterSweep(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitSweep" ):
                listener.exitSweep(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSweep" ):
                return visitor.visitSweep(self)
            else:
                return visitor.visitChildren(self)




    def sweep(self):

        localctx = AutolevParser.SweepContext(self, self._ctx, self.state)
        self.enterRule(localctx, 58, self.RULE_sweep)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 431
            self.match(AutolevParser.LBRACK)
            self.state = 432
            self.name()
            self.state = 436
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==51:
                self.state = 433
                self.match(AutolevParser.PRIME)
                self.state = 438
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 440
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 51539607550) != 0):
                self.state = 439
                self.unit()


            self.state = 442
            self.match(AutolevParser.EQUALS)
            self.state = 443
            self.expr(0)
            self.state = 444
            self.match(AutolevParser.COMMA)
            self.state = 445
            self.expr(0)
            self.state = 446
            self.match(AutolevParser.COMMA)
            self.state = 447
            self.expr(0)
            self.state = 448
            self.match(AutolevParser.RBRACK)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SaveStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def SAVE(self):
            return self.getToken(AutolevParser.SAVE, 0)

        def fileName(self):
            return self.getTypedRuleContext(AutolevParser.FileNameContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_saveStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterSaveStatement" ):
                listener.enterSaveStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitSaveStatement" ):
                listener.exitSaveStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSaveStatement" ):
                return visitor.visitSaveStatement(self)
            else:
                return visitor.visitChildren(self)




    def saveStatement(self):

        localctx = AutolevParser.SaveStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 60, self.RULE_saveStatement)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 450
            self.match(AutolevParser.SAVE)
            self.state = 451
            self.fileName()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class EncodeStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ENCODE(self):
            return self.getToken(AutolevParser.ENCODE, 0)

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_encodeStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterEncodeStatement" ):
                listener.enterEncodeStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitEncodeStatement" ):
                listener.exitEncodeStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEncodeStatement" ):
                return visitor.visitEncodeStatement(self)
            else:
                return visitor.visitChildren(self)




    def encodeStatement(self):

        localctx = AutolevParser.EncodeStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 62, self.RULE_encodeStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 453
            self.match(AutolevParser.ENCODE)
            self.state = 454
            self.expr(0)
            self.state = 459
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 455
                self.match(AutolevParser.COMMA)
                self.state = 456
                self.expr(0)
                self.state = 461
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class RunStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def RUN(self):
            return self.getToken(AutolevParser.RUN, 0)

        def fileName(self):
            return self.getTypedRuleContext(AutolevParser.FileNameContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_runStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterRunStatement" ):
                listener.enterRunStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitRunStatement" ):
                listener.exitRunStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRunStatement" ):
                return visitor.visitRunStatement(self)
            else:
                return visitor.visitChildren(self)




    def runStatement(self):

        localctx = AutolevParser.RunStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 64, self.RULE_runStatement)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 462
            self.match(AutolevParser.RUN)
            self.state = 463
            self.fileName()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExitStatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EXIT(self):
            return self.getToken(AutolevParser.EXIT, 0)

        def QUIT(self):
            return self.getToken(AutolevParser.QUIT, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_exitStatement

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterExitStatement" ):
                listener.enterExitStatement(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitExitStatement" ):
                listener.exitExitStatement(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExitStatement" ):
                return visitor.visitExitStatement(self)
            else:
                return visitor.visitChildren(self)




    def exitStatement(self):

        localctx = AutolevParser.ExitStatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 66, self.RULE_exitStatement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 465
            _la = self._input.LA(1)
            if not(_la==21 or _la==22):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class FileNameContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def fileNamePart(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.FileNamePartContext)
            else:
                return self.getTypedRuleContext(AutolevParser.FileNamePartContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_fileName

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterFileName" ):
                listener.enterFileName(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitFileName" ):
                listener.exitFileName(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFileName" ):
                return visitor.visitFileName(self)
            else:
                return visitor.visitChildren(self)




    def fileName(self):

        localctx = AutolevParser.FileNameContext(self, self._ctx, self.state)
        self.enterRule(localctx, 68, self.RULE_fileName)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 468 
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while True:
                self.state = 467
                self.fileNamePart()
                self.state = 470 
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if not ((((_la) & ~0x3f) == 0 and ((1 << _la) & 3459679565192888318) != 0)):
                    break

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class FileNamePartContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)


        def INT(self):
            return self.getToken(AutolevParser.INT, 0)

        def FLOAT(self):
            return self.getToken(AutolevParser.FLOAT, 0)

        def DOT(self):
            return self.getToken(AutolevParser.DOT, 0)

        def SLASH(self):
            return self.getToken(AutolevParser.SLASH, 0)

        def BACKSLASH(self):
            return self.getToken(AutolevParser.BACKSLASH, 0)

        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def COLON(self):
            return self.getToken(AutolevParser.COLON, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_fileNamePart

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterFileNamePart" ):
                listener.enterFileNamePart(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitFileNamePart" ):
                listener.exitFileNamePart(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFileNamePart" ):
                return visitor.visitFileNamePart(self)
            else:
                return visitor.visitChildren(self)




    def fileNamePart(self):

        localctx = AutolevParser.FileNamePartContext(self, self._ctx, self.state)
        self.enterRule(localctx, 70, self.RULE_fileNamePart)
        try:
            self.state = 480
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 35]:
                self.enterOuterAlt(localctx, 1)
                self.state = 472
                self.name()
                pass
            elif token in [37]:
                self.enterOuterAlt(localctx, 2)
                self.state = 473
                self.match(AutolevParser.INT)
                pass
            elif token in [36]:
                self.enterOuterAlt(localctx, 3)
                self.state = 474
                self.match(AutolevParser.FLOAT)
                pass
            elif token in [61]:
                self.enterOuterAlt(localctx, 4)
                self.state = 475
                self.match(AutolevParser.DOT)
                pass
            elif token in [48]:
                self.enterOuterAlt(localctx, 5)
                self.state = 476
                self.match(AutolevParser.SLASH)
                pass
            elif token in [49]:
                self.enterOuterAlt(localctx, 6)
                self.state = 477
                self.match(AutolevParser.BACKSLASH)
                pass
            elif token in [46]:
                self.enterOuterAlt(localctx, 7)
                self.state = 478
                self.match(AutolevParser.MINUS)
                pass
            elif token in [60]:
                self.enterOuterAlt(localctx, 8)
                self.state = 479
                self.match(AutolevParser.COLON)
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SettingContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def settingName(self):
            return self.getTypedRuleContext(AutolevParser.SettingNameContext,0)


        def settingValue(self):
            return self.getTypedRuleContext(AutolevParser.SettingValueContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_setting

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterSetting" ):
                listener.enterSetting(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitSetting" ):
                listener.exitSetting(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSetting" ):
                return visitor.visitSetting(self)
            else:
                return visitor.visitChildren(self)




    def setting(self):

        localctx = AutolevParser.SettingContext(self, self._ctx, self.state)
        self.enterRule(localctx, 72, self.RULE_setting)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 482
            self.settingName()
            self.state = 484
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 70626442215422) != 0):
                self.state = 483
                self.settingValue()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SettingNameContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def AUTOZ(self):
            return self.getToken(AutolevParser.AUTOZ, 0)

        def AUTORHS(self):
            return self.getToken(AutolevParser.AUTORHS, 0)

        def AUTOEPSILON(self):
            return self.getToken(AutolevParser.AUTOEPSILON, 0)

        def AUTOEXPRESS(self):
            return self.getToken(AutolevParser.AUTOEXPRESS, 0)

        def COMPLEX(self):
            return self.getToken(AutolevParser.COMPLEX, 0)

        def DEGREES(self):
            return self.getToken(AutolevParser.DEGREES, 0)

        def DIGITS(self):
            return self.getToken(AutolevParser.DIGITS, 0)

        def FACTORING(self):
            return self.getToken(AutolevParser.FACTORING, 0)

        def OVERWRITE(self):
            return self.getToken(AutolevParser.OVERWRITE, 0)

        def BEEPSOUND(self):
            return self.getToken(AutolevParser.BEEPSOUND, 0)

        def PAUSE(self):
            return self.getToken(AutolevParser.PAUSE, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_settingName

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterSettingName" ):
                listener.enterSettingName(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitSettingName" ):
                listener.exitSettingName(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSettingName" ):
                return visitor.visitSettingName(self)
            else:
                return visitor.visitChildren(self)




    def settingName(self):

        localctx = AutolevParser.SettingNameContext(self, self._ctx, self.state)
        self.enterRule(localctx, 74, self.RULE_settingName)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 486
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 17171480576) != 0)):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SettingValueContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)


        def number(self):
            return self.getTypedRuleContext(AutolevParser.NumberContext,0)


        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_settingValue

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterSettingValue" ):
                listener.enterSettingValue(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitSettingValue" ):
                listener.exitSettingValue(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSettingValue" ):
                return visitor.visitSettingValue(self)
            else:
                return visitor.visitChildren(self)




    def settingValue(self):

        localctx = AutolevParser.SettingValueContext(self, self._ctx, self.state)
        self.enterRule(localctx, 76, self.RULE_settingValue)
        self._la = 0 # Token type
        try:
            self.state = 493
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 35]:
                self.enterOuterAlt(localctx, 1)
                self.state = 488
                self.name()
                pass
            elif token in [36, 37, 46]:
                self.enterOuterAlt(localctx, 2)
                self.state = 490
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==46:
                    self.state = 489
                    self.match(AutolevParser.MINUS)


                self.state = 492
                self.number()
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExprContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return AutolevParser.RULE_expr

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)


    class UnaryExprContext(ExprContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.ExprContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)

        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)
        def PLUS(self):
            return self.getToken(AutolevParser.PLUS, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterUnaryExpr" ):
                listener.enterUnaryExpr(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitUnaryExpr" ):
                listener.exitUnaryExpr(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnaryExpr" ):
                return visitor.visitUnaryExpr(self)
            else:
                return visitor.visitChildren(self)


    class PowerExprContext(ExprContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.ExprContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)

        def CARET(self):
            return self.getToken(AutolevParser.CARET, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterPowerExpr" ):
                listener.enterPowerExpr(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitPowerExpr" ):
                listener.exitPowerExpr(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitPowerExpr" ):
                return visitor.visitPowerExpr(self)
            else:
                return visitor.visitChildren(self)


    class PrimaryExprContext(ExprContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.ExprContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def primary(self):
            return self.getTypedRuleContext(AutolevParser.PrimaryContext,0)


        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterPrimaryExpr" ):
                listener.enterPrimaryExpr(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitPrimaryExpr" ):
                listener.exitPrimaryExpr(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitPrimaryExpr" ):
                return visitor.visitPrimaryExpr(self)
            else:
                return visitor.visitChildren(self)


    class AddExprContext(ExprContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.ExprContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)

        def PLUS(self):
            return self.getToken(AutolevParser.PLUS, 0)
        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterAddExpr" ):
                listener.enterAddExpr(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitAddExpr" ):
                listener.exitAddExpr(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitAddExpr" ):
                return visitor.visitAddExpr(self)
            else:
                return visitor.visitChildren(self)


    class MulExprContext(ExprContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.ExprContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)

        def STAR(self):
            return self.getToken(AutolevParser.STAR, 0)
        def SLASH(self):
            return self.getToken(AutolevParser.SLASH, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterMulExpr" ):
                listener.enterMulExpr(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitMulExpr" ):
                listener.exitMulExpr(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMulExpr" ):
                return visitor.visitMulExpr(self)
            else:
                return visitor.visitChildren(self)



    def expr(self, _p:int=0):
        _parentctx = self._ctx
        _parentState = self.state
        localctx = AutolevParser.ExprContext(self, self._ctx, _parentState)
        _prevctx = localctx
        _startState = 78
        self.enterRecursionRule(localctx, 78, self.RULE_expr, _p)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 499
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [45, 46]:
                localctx = AutolevParser.UnaryExprContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx

                self.state = 496
                _la = self._input.LA(1)
                if not(_la==45 or _la==46):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                self.state = 497
                self.expr(4)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 52, 54]:
                localctx = AutolevParser.PrimaryExprContext(self, localctx)
                self._ctx = localctx
                _prevctx = localctx
                self.state = 498
                self.primary()
                pass
            else:
                raise NoViableAltException(self)

            self._ctx.stop = self._input.LT(-1)
            self.state = 512
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,64,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    if self._parseListeners is not None:
                        self.triggerExitRuleEvent()
                    _prevctx = localctx
                    self.state = 510
                    self._errHandler.sync(self)
                    la_ = self._interp.adaptivePredict(self._input,63,self._ctx)
                    if la_ == 1:
                        localctx = AutolevParser.PowerExprContext(self, AutolevParser.ExprContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expr)
                        self.state = 501
                        if not self.precpred(self._ctx, 5):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 5)")
                        self.state = 502
                        self.match(AutolevParser.CARET)
                        self.state = 503
                        self.expr(5)
                        pass

                    elif la_ == 2:
                        localctx = AutolevParser.MulExprContext(self, AutolevParser.ExprContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expr)
                        self.state = 504
                        if not self.precpred(self._ctx, 3):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 3)")
                        self.state = 505
                        _la = self._input.LA(1)
                        if not(_la==47 or _la==48):
                            self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 506
                        self.expr(4)
                        pass

                    elif la_ == 3:
                        localctx = AutolevParser.AddExprContext(self, AutolevParser.ExprContext(self, _parentctx, _parentState))
                        self.pushNewRecursionContext(localctx, _startState, self.RULE_expr)
                        self.state = 507
                        if not self.precpred(self._ctx, 2):
                            from antlr4.error.Errors import FailedPredicateException
                            raise FailedPredicateException(self, "self.precpred(self._ctx, 2)")
                        self.state = 508
                        _la = self._input.LA(1)
                        if not(_la==45 or _la==46):
                            self._errHandler.recoverInline(self)
                        else:
                            self._errHandler.reportMatch(self)
                            self.consume()
                        self.state = 509
                        self.expr(3)
                        pass

             
                self.state = 514
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,64,self._ctx)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.unrollRecursionContexts(_parentctx)
        return localctx


    class PrimaryContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return AutolevParser.RULE_primary

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class NameAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)

        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterNameAtom" ):
                listener.enterNameAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitNameAtom" ):
                listener.exitNameAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNameAtom" ):
                return visitor.visitNameAtom(self)
            else:
                return visitor.visitChildren(self)


    class CallAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)

        def LPAREN(self):
            return self.getToken(AutolevParser.LPAREN, 0)
        def RPAREN(self):
            return self.getToken(AutolevParser.RPAREN, 0)
        def argList(self):
            return self.getTypedRuleContext(AutolevParser.ArgListContext,0)


        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterCallAtom" ):
                listener.enterCallAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitCallAtom" ):
                listener.exitCallAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitCallAtom" ):
                return visitor.visitCallAtom(self)
            else:
                return visitor.visitChildren(self)


    class VectorAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def VECNAME(self):
            return self.getToken(AutolevParser.VECNAME, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterVectorAtom" ):
                listener.enterVectorAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitVectorAtom" ):
                listener.exitVectorAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitVectorAtom" ):
                return visitor.visitVectorAtom(self)
            else:
                return visitor.visitChildren(self)


    class RangeAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)

        def declRange(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.DeclRangeContext)
            else:
                return self.getTypedRuleContext(AutolevParser.DeclRangeContext,i)

        def ID(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.ID)
            else:
                return self.getToken(AutolevParser.ID, i)
        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterRangeAtom" ):
                listener.enterRangeAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitRangeAtom" ):
                listener.exitRangeAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitRangeAtom" ):
                return visitor.visitRangeAtom(self)
            else:
                return visitor.visitChildren(self)


    class ParenAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def LPAREN(self):
            return self.getToken(AutolevParser.LPAREN, 0)
        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)

        def RPAREN(self):
            return self.getToken(AutolevParser.RPAREN, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterParenAtom" ):
                listener.enterParenAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitParenAtom" ):
                listener.exitParenAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitParenAtom" ):
                return visitor.visitParenAtom(self)
            else:
                return visitor.visitChildren(self)


    class IndexAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def name(self):
            return self.getTypedRuleContext(AutolevParser.NameContext,0)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def indexList(self):
            return self.getTypedRuleContext(AutolevParser.IndexListContext,0)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)
        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterIndexAtom" ):
                listener.enterIndexAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitIndexAtom" ):
                listener.exitIndexAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIndexAtom" ):
                return visitor.visitIndexAtom(self)
            else:
                return visitor.visitChildren(self)


    class EmptyMatrixAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterEmptyMatrixAtom" ):
                listener.enterEmptyMatrixAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitEmptyMatrixAtom" ):
                listener.exitEmptyMatrixAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitEmptyMatrixAtom" ):
                return visitor.visitEmptyMatrixAtom(self)
            else:
                return visitor.visitChildren(self)


    class MatrixAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def matrixRow(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.MatrixRowContext)
            else:
                return self.getTypedRuleContext(AutolevParser.MatrixRowContext,i)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)
        def SEMI(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.SEMI)
            else:
                return self.getToken(AutolevParser.SEMI, i)

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterMatrixAtom" ):
                listener.enterMatrixAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitMatrixAtom" ):
                listener.exitMatrixAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMatrixAtom" ):
                return visitor.visitMatrixAtom(self)
            else:
                return visitor.visitChildren(self)


    class NumberAtomContext(PrimaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.PrimaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def number(self):
            return self.getTypedRuleContext(AutolevParser.NumberContext,0)


        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterNumberAtom" ):
                listener.enterNumberAtom(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitNumberAtom" ):
                listener.exitNumberAtom(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNumberAtom" ):
                return visitor.visitNumberAtom(self)
            else:
                return visitor.visitChildren(self)



    def primary(self):

        localctx = AutolevParser.PrimaryContext(self, self._ctx, self.state)
        self.enterRule(localctx, 80, self.RULE_primary)
        self._la = 0 # Token type
        try:
            self.state = 579
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,73,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.NumberAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 515
                self.number()
                pass

            elif la_ == 2:
                localctx = AutolevParser.VectorAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 516
                self.match(AutolevParser.VECNAME)
                pass

            elif la_ == 3:
                localctx = AutolevParser.CallAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 517
                self.name()
                self.state = 518
                self.match(AutolevParser.LPAREN)
                self.state = 520
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 22623826131025918) != 0):
                    self.state = 519
                    self.argList()


                self.state = 522
                self.match(AutolevParser.RPAREN)
                pass

            elif la_ == 4:
                localctx = AutolevParser.IndexAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 4)
                self.state = 524
                self.name()
                self.state = 528
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==51:
                    self.state = 525
                    self.match(AutolevParser.PRIME)
                    self.state = 530
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 531
                self.match(AutolevParser.LBRACK)
                self.state = 532
                self.indexList()
                self.state = 533
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 5:
                localctx = AutolevParser.RangeAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 5)
                self.state = 535
                self.name()
                self.state = 536
                self.declRange()
                self.state = 543
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,68,self._ctx)
                while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                    if _alt==1:
                        self.state = 538
                        self._errHandler.sync(self)
                        _la = self._input.LA(1)
                        if _la==35:
                            self.state = 537
                            self.match(AutolevParser.ID)


                        self.state = 540
                        self.declRange() 
                    self.state = 545
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,68,self._ctx)

                self.state = 547
                self._errHandler.sync(self)
                la_ = self._interp.adaptivePredict(self._input,69,self._ctx)
                if la_ == 1:
                    self.state = 546
                    self.match(AutolevParser.ID)


                self.state = 552
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,70,self._ctx)
                while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                    if _alt==1:
                        self.state = 549
                        self.match(AutolevParser.PRIME) 
                    self.state = 554
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,70,self._ctx)

                pass

            elif la_ == 6:
                localctx = AutolevParser.NameAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 555
                self.name()
                self.state = 559
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,71,self._ctx)
                while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                    if _alt==1:
                        self.state = 556
                        self.match(AutolevParser.PRIME) 
                    self.state = 561
                    self._errHandler.sync(self)
                    _alt = self._interp.adaptivePredict(self._input,71,self._ctx)

                pass

            elif la_ == 7:
                localctx = AutolevParser.MatrixAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 562
                self.match(AutolevParser.LBRACK)
                self.state = 563
                self.matrixRow()
                self.state = 568
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==59:
                    self.state = 564
                    self.match(AutolevParser.SEMI)
                    self.state = 565
                    self.matrixRow()
                    self.state = 570
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 571
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 8:
                localctx = AutolevParser.EmptyMatrixAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 573
                self.match(AutolevParser.LBRACK)
                self.state = 574
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 9:
                localctx = AutolevParser.ParenAtomContext(self, localctx)
                self.enterOuterAlt(localctx, 9)
                self.state = 575
                self.match(AutolevParser.LPAREN)
                self.state = 576
                self.expr(0)
                self.state = 577
                self.match(AutolevParser.RPAREN)
                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class MatrixRowContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_matrixRow

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterMatrixRow" ):
                listener.enterMatrixRow(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitMatrixRow" ):
                listener.exitMatrixRow(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMatrixRow" ):
                return visitor.visitMatrixRow(self)
            else:
                return visitor.visitChildren(self)




    def matrixRow(self):

        localctx = AutolevParser.MatrixRowContext(self, self._ctx, self.state)
        self.enterRule(localctx, 82, self.RULE_matrixRow)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 581
            self.expr(0)
            self.state = 586
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 582
                self.match(AutolevParser.COMMA)
                self.state = 583
                self.expr(0)
                self.state = 588
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class IndexListContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def indexItem(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.IndexItemContext)
            else:
                return self.getTypedRuleContext(AutolevParser.IndexItemContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_indexList

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterIndexList" ):
                listener.enterIndexList(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitIndexList" ):
                listener.exitIndexList(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIndexList" ):
                return visitor.visitIndexList(self)
            else:
                return visitor.visitChildren(self)




    def indexList(self):

        localctx = AutolevParser.IndexListContext(self, self._ctx, self.state)
        self.enterRule(localctx, 84, self.RULE_indexList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 589
            self.indexItem()
            self.state = 594
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 590
                self.match(AutolevParser.COMMA)
                self.state = 591
                self.indexItem()
                self.state = 596
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class IndexItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def COLON(self):
            return self.getToken(AutolevParser.COLON, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_indexItem

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterIndexItem" ):
                listener.enterIndexItem(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitIndexItem" ):
                listener.exitIndexItem(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIndexItem" ):
                return visitor.visitIndexItem(self)
            else:
                return visitor.visitChildren(self)




    def indexItem(self):

        localctx = AutolevParser.IndexItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 86, self.RULE_indexItem)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 597
            self.expr(0)
            self.state = 600
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==60:
                self.state = 598
                self.match(AutolevParser.COLON)
                self.state = 599
                self.expr(0)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ArgListContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def arg(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ArgContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ArgContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_argList

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterArgList" ):
                listener.enterArgList(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitArgList" ):
                listener.exitArgList(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitArgList" ):
                return visitor.visitArgList(self)
            else:
                return visitor.visitChildren(self)




    def argList(self):

        localctx = AutolevParser.ArgListContext(self, self._ctx, self.state)
        self.enterRule(localctx, 88, self.RULE_argList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 602
            self.arg()
            self.state = 607
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==58:
                self.state = 603
                self.match(AutolevParser.COMMA)
                self.state = 604
                self.arg()
                self.state = 609
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ArgContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def COLON(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COLON)
            else:
                return self.getToken(AutolevParser.COLON, i)

        def EQUALS(self):
            return self.getToken(AutolevParser.EQUALS, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_arg

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterArg" ):
                listener.enterArg(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitArg" ):
                listener.exitArg(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitArg" ):
                return visitor.visitArg(self)
            else:
                return visitor.visitChildren(self)




    def arg(self):

        localctx = AutolevParser.ArgContext(self, self._ctx, self.state)
        self.enterRule(localctx, 90, self.RULE_arg)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 610
            self.expr(0)
            self.state = 613
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==60:
                self.state = 611
                self.match(AutolevParser.COLON)
                self.state = 612
                self.expr(0)


            self.state = 621
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==44:
                self.state = 615
                self.match(AutolevParser.EQUALS)
                self.state = 616
                self.expr(0)
                self.state = 619
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==60:
                    self.state = 617
                    self.match(AutolevParser.COLON)
                    self.state = 618
                    self.expr(0)




        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class NumberContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def INT(self):
            return self.getToken(AutolevParser.INT, 0)

        def FLOAT(self):
            return self.getToken(AutolevParser.FLOAT, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_number

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterNumber" ):
                listener.enterNumber(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitNumber" ):
                listener.exitNumber(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNumber" ):
                return visitor.visitNumber(self)
            else:
                return visitor.visitChildren(self)




    def number(self):

        localctx = AutolevParser.NumberContext(self, self._ctx, self.state)
        self.enterRule(localctx, 92, self.RULE_number)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 623
            _la = self._input.LA(1)
            if not(_la==36 or _la==37):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class NameContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ID(self):
            return self.getToken(AutolevParser.ID, 0)

        def NEWTONIAN(self):
            return self.getToken(AutolevParser.NEWTONIAN, 0)

        def FRAMES(self):
            return self.getToken(AutolevParser.FRAMES, 0)

        def BODIES(self):
            return self.getToken(AutolevParser.BODIES, 0)

        def PARTICLES(self):
            return self.getToken(AutolevParser.PARTICLES, 0)

        def POINTS(self):
            return self.getToken(AutolevParser.POINTS, 0)

        def CONSTANTS(self):
            return self.getToken(AutolevParser.CONSTANTS, 0)

        def VARIABLES(self):
            return self.getToken(AutolevParser.VARIABLES, 0)

        def MOTIONVARIABLES(self):
            return self.getToken(AutolevParser.MOTIONVARIABLES, 0)

        def SPECIFIED(self):
            return self.getToken(AutolevParser.SPECIFIED, 0)

        def IMAGINARY(self):
            return self.getToken(AutolevParser.IMAGINARY, 0)

        def MASS(self):
            return self.getToken(AutolevParser.MASS, 0)

        def INERTIA(self):
            return self.getToken(AutolevParser.INERTIA, 0)

        def INPUT(self):
            return self.getToken(AutolevParser.INPUT, 0)

        def OUTPUT(self):
            return self.getToken(AutolevParser.OUTPUT, 0)

        def UNITS(self):
            return self.getToken(AutolevParser.UNITS, 0)

        def UNITSYSTEM(self):
            return self.getToken(AutolevParser.UNITSYSTEM, 0)

        def CODE(self):
            return self.getToken(AutolevParser.CODE, 0)

        def SAVE(self):
            return self.getToken(AutolevParser.SAVE, 0)

        def ENCODE(self):
            return self.getToken(AutolevParser.ENCODE, 0)

        def RUN(self):
            return self.getToken(AutolevParser.RUN, 0)

        def EXIT(self):
            return self.getToken(AutolevParser.EXIT, 0)

        def QUIT(self):
            return self.getToken(AutolevParser.QUIT, 0)

        def AUTOZ(self):
            return self.getToken(AutolevParser.AUTOZ, 0)

        def AUTORHS(self):
            return self.getToken(AutolevParser.AUTORHS, 0)

        def AUTOEPSILON(self):
            return self.getToken(AutolevParser.AUTOEPSILON, 0)

        def AUTOEXPRESS(self):
            return self.getToken(AutolevParser.AUTOEXPRESS, 0)

        def COMPLEX(self):
            return self.getToken(AutolevParser.COMPLEX, 0)

        def DEGREES(self):
            return self.getToken(AutolevParser.DEGREES, 0)

        def DIGITS(self):
            return self.getToken(AutolevParser.DIGITS, 0)

        def FACTORING(self):
            return self.getToken(AutolevParser.FACTORING, 0)

        def OVERWRITE(self):
            return self.getToken(AutolevParser.OVERWRITE, 0)

        def BEEPSOUND(self):
            return self.getToken(AutolevParser.BEEPSOUND, 0)

        def PAUSE(self):
            return self.getToken(AutolevParser.PAUSE, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_name

        def enterRule(self, listener:ParseTreeListener):
            if hasattr( listener, "enterName" ):
                listener.enterName(self)

        def exitRule(self, listener:ParseTreeListener):
            if hasattr( listener, "exitName" ):
                listener.exitName(self)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitName" ):
                return visitor.visitName(self)
            else:
                return visitor.visitChildren(self)




    def name(self):

        localctx = AutolevParser.NameContext(self, self._ctx, self.state)
        self.enterRule(localctx, 94, self.RULE_name)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 625
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 51539607550) != 0)):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx



    def sempred(self, localctx:RuleContext, ruleIndex:int, predIndex:int):
        if self._predicates == None:
            self._predicates = dict()
        self._predicates[39] = self.expr_sempred
        pred = self._predicates.get(ruleIndex, None)
        if pred is None:
            raise Exception("No predicate with index:" + str(ruleIndex))
        else:
            return pred(localctx, predIndex)

    def expr_sempred(self, localctx:ExprContext, predIndex:int):
            if predIndex == 0:
                return self.precpred(self._ctx, 5)
         

            if predIndex == 1:
                return self.precpred(self._ctx, 3)
         

            if predIndex == 2:
                return self.precpred(self._ctx, 2)
         




