"""whipple_benchmark: its equations of motion as SymPy expressions, written by autolev from
whipple_benchmark.al (CODE DYNAMICS whipple_benchmark.c).

Level: equations.  The state, the rates given explicitly, and the mass matrix and
forcing from which the other rates (`unknowns`) are solved, as Autolev's Kane's
method formed them, with every intermediate (Autolev's Z's) a named assignment.
Not the mechanics level: sympy's KanesMethod here takes no dependent or auxiliary speeds
(U1, U2, U3, U5, U8).
Importing defines `system` (a sympy.physics.mechanics.SymbolicSystem: full_mass *
d(states)/dt = full_forcing, in the intermediates), `constants`,
`initial_conditions` and `specified`;
`python THIS.py [OUT.csv]` integrates from TINITIAL to TFINAL with scipy (DOP853,
RELERR and ABSERR) and writes the OUTPUT columns as CSV.
"""
import sys

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me
from scipy.integrate import solve_ivp

t = me.dynamicsymbols._t

# the state: functions of time
Q1 = me.dynamicsymbols('Q1')
Q2 = me.dynamicsymbols('Q2')
Q3 = me.dynamicsymbols('Q3')
Q4 = me.dynamicsymbols('Q4')
Q5 = me.dynamicsymbols('Q5')
Q6 = me.dynamicsymbols('Q6')
Q7 = me.dynamicsymbols('Q7')
Q8 = me.dynamicsymbols('Q8')
U4 = me.dynamicsymbols('U4')
U6 = me.dynamicsymbols('U6')
U7 = me.dynamicsymbols('U7')

# constants
CT = sm.Symbol('CT')
G = sm.Symbol('G')
IBXX = sm.Symbol('IBXX')
IBXZ = sm.Symbol('IBXZ')
IBYY = sm.Symbol('IBYY')
IBZZ = sm.Symbol('IBZZ')
IFXX = sm.Symbol('IFXX')
IFYY = sm.Symbol('IFYY')
IHXX = sm.Symbol('IHXX')
IHXZ = sm.Symbol('IHXZ')
IHYY = sm.Symbol('IHYY')
IHZZ = sm.Symbol('IHZZ')
IRXX = sm.Symbol('IRXX')
IRYY = sm.Symbol('IRYY')
LAM = sm.Symbol('LAM')
MB = sm.Symbol('MB')
MF = sm.Symbol('MF')
MH = sm.Symbol('MH')
MR = sm.Symbol('MR')
RF = sm.Symbol('RF')
RR = sm.Symbol('RR')
W = sm.Symbol('W')
XB = sm.Symbol('XB')
XH = sm.Symbol('XH')
ZB = sm.Symbol('ZB')
ZH = sm.Symbol('ZH')

# the rates solved from the mass matrix
U4p = U4.diff(t)
U6p = U6.diff(t)
U7p = U7.diff(t)

# intermediates (Autolev's Z's) and the model's definitions, as functions of
# time, and what each is, in the order they are computed; `expanded(expr)`
# replaces them in an expression
z3 = me.dynamicsymbols('z3')
z4 = me.dynamicsymbols('z4')
z11 = me.dynamicsymbols('z11')
z7 = me.dynamicsymbols('z7')
z14 = me.dynamicsymbols('z14')
z61 = me.dynamicsymbols('z61')
z1 = me.dynamicsymbols('z1')
z5 = me.dynamicsymbols('z5')
z65 = me.dynamicsymbols('z65')
z66 = me.dynamicsymbols('z66')
z2 = me.dynamicsymbols('z2')
z6 = me.dynamicsymbols('z6')
z69 = me.dynamicsymbols('z69')
z71 = me.dynamicsymbols('z71')
z9 = me.dynamicsymbols('z9')
z58 = me.dynamicsymbols('z58')
z59 = me.dynamicsymbols('z59')
z10 = me.dynamicsymbols('z10')
z15 = me.dynamicsymbols('z15')
z60 = me.dynamicsymbols('z60')
z62 = me.dynamicsymbols('z62')
z63 = me.dynamicsymbols('z63')
z8 = me.dynamicsymbols('z8')
z64 = me.dynamicsymbols('z64')
z67 = me.dynamicsymbols('z67')
z68 = me.dynamicsymbols('z68')
z70 = me.dynamicsymbols('z70')
z72 = me.dynamicsymbols('z72')
z73 = me.dynamicsymbols('z73')
z74 = me.dynamicsymbols('z74')
z75 = me.dynamicsymbols('z75')
z76 = me.dynamicsymbols('z76')
Q6p = me.dynamicsymbols('Q6p')
Q7p = me.dynamicsymbols('Q7p')
z28 = me.dynamicsymbols('z28')
z29 = me.dynamicsymbols('z29')
Q4p = me.dynamicsymbols('Q4p')
z24 = me.dynamicsymbols('z24')
z32 = me.dynamicsymbols('z32')
z36 = me.dynamicsymbols('z36')
z50 = me.dynamicsymbols('z50')
z51 = me.dynamicsymbols('z51')
z54 = me.dynamicsymbols('z54')
z25 = me.dynamicsymbols('z25')
z33 = me.dynamicsymbols('z33')
z37 = me.dynamicsymbols('z37')
z55 = me.dynamicsymbols('z55')
z77 = me.dynamicsymbols('z77')
z78 = me.dynamicsymbols('z78')
z79 = me.dynamicsymbols('z79')
z80 = me.dynamicsymbols('z80')
z81 = me.dynamicsymbols('z81')
U1 = me.dynamicsymbols('U1')
z82 = me.dynamicsymbols('z82')
z83 = me.dynamicsymbols('z83')
z84 = me.dynamicsymbols('z84')
U2 = me.dynamicsymbols('U2')
z85 = me.dynamicsymbols('z85')
z86 = me.dynamicsymbols('z86')
z87 = me.dynamicsymbols('z87')
z88 = me.dynamicsymbols('z88')
z89 = me.dynamicsymbols('z89')
z90 = me.dynamicsymbols('z90')
z91 = me.dynamicsymbols('z91')
z92 = me.dynamicsymbols('z92')
z93 = me.dynamicsymbols('z93')
z94 = me.dynamicsymbols('z94')
U3 = me.dynamicsymbols('U3')
z95 = me.dynamicsymbols('z95')
z96 = me.dynamicsymbols('z96')
z97 = me.dynamicsymbols('z97')
z98 = me.dynamicsymbols('z98')
U5 = me.dynamicsymbols('U5')
z99 = me.dynamicsymbols('z99')
z100 = me.dynamicsymbols('z100')
z101 = me.dynamicsymbols('z101')
z102 = me.dynamicsymbols('z102')
z103 = me.dynamicsymbols('z103')
z104 = me.dynamicsymbols('z104')
U8 = me.dynamicsymbols('U8')
z185 = me.dynamicsymbols('z185')
z186 = me.dynamicsymbols('z186')
z203 = me.dynamicsymbols('z203')
z182 = me.dynamicsymbols('z182')
z183 = me.dynamicsymbols('z183')
z184 = me.dynamicsymbols('z184')
z187 = me.dynamicsymbols('z187')
z188 = me.dynamicsymbols('z188')
z204 = me.dynamicsymbols('z204')
z205 = me.dynamicsymbols('z205')
z207 = me.dynamicsymbols('z207')
z252 = me.dynamicsymbols('z252')
z255 = me.dynamicsymbols('z255')
z256 = me.dynamicsymbols('z256')
z280 = me.dynamicsymbols('z280')
z291 = me.dynamicsymbols('z291')
z208 = me.dynamicsymbols('z208')
z222 = me.dynamicsymbols('z222')
z224 = me.dynamicsymbols('z224')
z265 = me.dynamicsymbols('z265')
z266 = me.dynamicsymbols('z266')
z286 = me.dynamicsymbols('z286')
z292 = me.dynamicsymbols('z292')
z225 = me.dynamicsymbols('z225')
z226 = me.dynamicsymbols('z226')
z227 = me.dynamicsymbols('z227')
z228 = me.dynamicsymbols('z228')
z229 = me.dynamicsymbols('z229')
z243 = me.dynamicsymbols('z243')
z244 = me.dynamicsymbols('z244')
z246 = me.dynamicsymbols('z246')
z273 = me.dynamicsymbols('z273')
z274 = me.dynamicsymbols('z274')
z275 = me.dynamicsymbols('z275')
z276 = me.dynamicsymbols('z276')
z290 = me.dynamicsymbols('z290')
z293 = me.dynamicsymbols('z293')
z189 = me.dynamicsymbols('z189')
z190 = me.dynamicsymbols('z190')
z191 = me.dynamicsymbols('z191')
z192 = me.dynamicsymbols('z192')
z193 = me.dynamicsymbols('z193')
z194 = me.dynamicsymbols('z194')
z195 = me.dynamicsymbols('z195')
z196 = me.dynamicsymbols('z196')
z197 = me.dynamicsymbols('z197')
z198 = me.dynamicsymbols('z198')
z199 = me.dynamicsymbols('z199')
z200 = me.dynamicsymbols('z200')
z201 = me.dynamicsymbols('z201')
z202 = me.dynamicsymbols('z202')
z206 = me.dynamicsymbols('z206')
z247 = me.dynamicsymbols('z247')
z248 = me.dynamicsymbols('z248')
z249 = me.dynamicsymbols('z249')
z250 = me.dynamicsymbols('z250')
z251 = me.dynamicsymbols('z251')
z253 = me.dynamicsymbols('z253')
z254 = me.dynamicsymbols('z254')
z277 = me.dynamicsymbols('z277')
z278 = me.dynamicsymbols('z278')
z279 = me.dynamicsymbols('z279')
z333 = me.dynamicsymbols('z333')
z335 = me.dynamicsymbols('z335')
z336 = me.dynamicsymbols('z336')
z338 = me.dynamicsymbols('z338')
z425 = me.dynamicsymbols('z425')
z427 = me.dynamicsymbols('z427')
z430 = me.dynamicsymbols('z430')
z432 = me.dynamicsymbols('z432')
z453 = me.dynamicsymbols('z453')
z454 = me.dynamicsymbols('z454')
z455 = me.dynamicsymbols('z455')
z456 = me.dynamicsymbols('z456')
z466 = me.dynamicsymbols('z466')
z469 = me.dynamicsymbols('z469')
z472 = me.dynamicsymbols('z472')
z475 = me.dynamicsymbols('z475')
z476 = me.dynamicsymbols('z476')
z479 = me.dynamicsymbols('z479')
z480 = me.dynamicsymbols('z480')
z483 = me.dynamicsymbols('z483')
z486 = me.dynamicsymbols('z486')
z489 = me.dynamicsymbols('z489')
z492 = me.dynamicsymbols('z492')
z495 = me.dynamicsymbols('z495')
z498 = me.dynamicsymbols('z498')
z209 = me.dynamicsymbols('z209')
z210 = me.dynamicsymbols('z210')
z211 = me.dynamicsymbols('z211')
z212 = me.dynamicsymbols('z212')
z213 = me.dynamicsymbols('z213')
z214 = me.dynamicsymbols('z214')
z216 = me.dynamicsymbols('z216')
z217 = me.dynamicsymbols('z217')
z218 = me.dynamicsymbols('z218')
z219 = me.dynamicsymbols('z219')
z220 = me.dynamicsymbols('z220')
z223 = me.dynamicsymbols('z223')
z257 = me.dynamicsymbols('z257')
z258 = me.dynamicsymbols('z258')
z259 = me.dynamicsymbols('z259')
z260 = me.dynamicsymbols('z260')
z261 = me.dynamicsymbols('z261')
z262 = me.dynamicsymbols('z262')
z263 = me.dynamicsymbols('z263')
z264 = me.dynamicsymbols('z264')
z281 = me.dynamicsymbols('z281')
z282 = me.dynamicsymbols('z282')
z283 = me.dynamicsymbols('z283')
z284 = me.dynamicsymbols('z284')
z285 = me.dynamicsymbols('z285')
z467 = me.dynamicsymbols('z467')
z470 = me.dynamicsymbols('z470')
z473 = me.dynamicsymbols('z473')
z477 = me.dynamicsymbols('z477')
z481 = me.dynamicsymbols('z481')
z484 = me.dynamicsymbols('z484')
z487 = me.dynamicsymbols('z487')
z490 = me.dynamicsymbols('z490')
z457 = me.dynamicsymbols('z457')
z458 = me.dynamicsymbols('z458')
z493 = me.dynamicsymbols('z493')
z496 = me.dynamicsymbols('z496')
z499 = me.dynamicsymbols('z499')
z230 = me.dynamicsymbols('z230')
z231 = me.dynamicsymbols('z231')
z232 = me.dynamicsymbols('z232')
z233 = me.dynamicsymbols('z233')
z234 = me.dynamicsymbols('z234')
z235 = me.dynamicsymbols('z235')
z236 = me.dynamicsymbols('z236')
z237 = me.dynamicsymbols('z237')
z238 = me.dynamicsymbols('z238')
z239 = me.dynamicsymbols('z239')
z240 = me.dynamicsymbols('z240')
z241 = me.dynamicsymbols('z241')
z242 = me.dynamicsymbols('z242')
z245 = me.dynamicsymbols('z245')
z267 = me.dynamicsymbols('z267')
z268 = me.dynamicsymbols('z268')
z269 = me.dynamicsymbols('z269')
z270 = me.dynamicsymbols('z270')
z271 = me.dynamicsymbols('z271')
z272 = me.dynamicsymbols('z272')
z287 = me.dynamicsymbols('z287')
z288 = me.dynamicsymbols('z288')
z289 = me.dynamicsymbols('z289')
z468 = me.dynamicsymbols('z468')
z471 = me.dynamicsymbols('z471')
z474 = me.dynamicsymbols('z474')
z478 = me.dynamicsymbols('z478')
z482 = me.dynamicsymbols('z482')
z485 = me.dynamicsymbols('z485')
z488 = me.dynamicsymbols('z488')
z491 = me.dynamicsymbols('z491')
z459 = me.dynamicsymbols('z459')
z460 = me.dynamicsymbols('z460')
z461 = me.dynamicsymbols('z461')
z462 = me.dynamicsymbols('z462')
z494 = me.dynamicsymbols('z494')
z497 = me.dynamicsymbols('z497')
z500 = me.dynamicsymbols('z500')
z215 = me.dynamicsymbols('z215')
z221 = me.dynamicsymbols('z221')
z501 = me.dynamicsymbols('z501')
z502 = me.dynamicsymbols('z502')
z503 = me.dynamicsymbols('z503')
z504 = me.dynamicsymbols('z504')
z505 = me.dynamicsymbols('z505')
z506 = me.dynamicsymbols('z506')
Q3p = me.dynamicsymbols('Q3p')
z18 = me.dynamicsymbols('z18')
z300 = me.dynamicsymbols('z300')
z301 = me.dynamicsymbols('z301')
Q5p = me.dynamicsymbols('Q5p')
z16 = me.dynamicsymbols('z16')
z17 = me.dynamicsymbols('z17')
z304 = me.dynamicsymbols('z304')
z305 = me.dynamicsymbols('z305')
z314 = me.dynamicsymbols('z314')
z316 = me.dynamicsymbols('z316')
z317 = me.dynamicsymbols('z317')
z318 = me.dynamicsymbols('z318')
z315 = me.dynamicsymbols('z315')
z319 = me.dynamicsymbols('z319')
z320 = me.dynamicsymbols('z320')
z321 = me.dynamicsymbols('z321')
z322 = me.dynamicsymbols('z322')
z323 = me.dynamicsymbols('z323')
z324 = me.dynamicsymbols('z324')
z347 = me.dynamicsymbols('z347')
z349 = me.dynamicsymbols('z349')
z350 = me.dynamicsymbols('z350')
z351 = me.dynamicsymbols('z351')
z343 = me.dynamicsymbols('z343')
z352 = me.dynamicsymbols('z352')
z353 = me.dynamicsymbols('z353')
z348 = me.dynamicsymbols('z348')
z354 = me.dynamicsymbols('z354')
z334 = me.dynamicsymbols('z334')
z337 = me.dynamicsymbols('z337')
z355 = me.dynamicsymbols('z355')
z340 = me.dynamicsymbols('z340')
z342 = me.dynamicsymbols('z342')
z356 = me.dynamicsymbols('z356')
z339 = me.dynamicsymbols('z339')
z341 = me.dynamicsymbols('z341')
z357 = me.dynamicsymbols('z357')
z23 = me.dynamicsymbols('z23')
z41 = me.dynamicsymbols('z41')
z370 = me.dynamicsymbols('z370')
z371 = me.dynamicsymbols('z371')
z38 = me.dynamicsymbols('z38')
z39 = me.dynamicsymbols('z39')
z376 = me.dynamicsymbols('z376')
z377 = me.dynamicsymbols('z377')
z392 = me.dynamicsymbols('z392')
z393 = me.dynamicsymbols('z393')
z395 = me.dynamicsymbols('z395')
z396 = me.dynamicsymbols('z396')
z394 = me.dynamicsymbols('z394')
z397 = me.dynamicsymbols('z397')
z398 = me.dynamicsymbols('z398')
z399 = me.dynamicsymbols('z399')
z400 = me.dynamicsymbols('z400')
z401 = me.dynamicsymbols('z401')
z402 = me.dynamicsymbols('z402')
z31 = me.dynamicsymbols('z31')
z407 = me.dynamicsymbols('z407')
z408 = me.dynamicsymbols('z408')
z411 = me.dynamicsymbols('z411')
z412 = me.dynamicsymbols('z412')
Q8p = me.dynamicsymbols('Q8p')
z440 = me.dynamicsymbols('z440')
z442 = me.dynamicsymbols('z442')
z443 = me.dynamicsymbols('z443')
z444 = me.dynamicsymbols('z444')
z441 = me.dynamicsymbols('z441')
z445 = me.dynamicsymbols('z445')
z446 = me.dynamicsymbols('z446')
z426 = me.dynamicsymbols('z426')
z428 = me.dynamicsymbols('z428')
z447 = me.dynamicsymbols('z447')
z448 = me.dynamicsymbols('z448')
z449 = me.dynamicsymbols('z449')
z429 = me.dynamicsymbols('z429')
z431 = me.dynamicsymbols('z431')
z450 = me.dynamicsymbols('z450')
z434 = me.dynamicsymbols('z434')
z436 = me.dynamicsymbols('z436')
z451 = me.dynamicsymbols('z451')
z433 = me.dynamicsymbols('z433')
z435 = me.dynamicsymbols('z435')
z452 = me.dynamicsymbols('z452')
z507 = me.dynamicsymbols('z507')
z508 = me.dynamicsymbols('z508')
z509 = me.dynamicsymbols('z509')
z105 = me.dynamicsymbols('z105')
z510 = me.dynamicsymbols('z510')
z511 = me.dynamicsymbols('z511')
z515 = me.dynamicsymbols('z515')
z111 = me.dynamicsymbols('z111')
z516 = me.dynamicsymbols('z516')
z517 = me.dynamicsymbols('z517')
z106 = me.dynamicsymbols('z106')
z107 = me.dynamicsymbols('z107')
z108 = me.dynamicsymbols('z108')
z109 = me.dynamicsymbols('z109')
z110 = me.dynamicsymbols('z110')
z112 = me.dynamicsymbols('z112')
z113 = me.dynamicsymbols('z113')
z114 = me.dynamicsymbols('z114')
z115 = me.dynamicsymbols('z115')
z116 = me.dynamicsymbols('z116')
z117 = me.dynamicsymbols('z117')
z118 = me.dynamicsymbols('z118')
z119 = me.dynamicsymbols('z119')
z120 = me.dynamicsymbols('z120')
z121 = me.dynamicsymbols('z121')
z122 = me.dynamicsymbols('z122')
z123 = me.dynamicsymbols('z123')
z124 = me.dynamicsymbols('z124')
z125 = me.dynamicsymbols('z125')
z126 = me.dynamicsymbols('z126')
z127 = me.dynamicsymbols('z127')
z128 = me.dynamicsymbols('z128')
z129 = me.dynamicsymbols('z129')
z130 = me.dynamicsymbols('z130')
z131 = me.dynamicsymbols('z131')
z132 = me.dynamicsymbols('z132')
z133 = me.dynamicsymbols('z133')
z134 = me.dynamicsymbols('z134')
z135 = me.dynamicsymbols('z135')
z136 = me.dynamicsymbols('z136')
z512 = me.dynamicsymbols('z512')
z513 = me.dynamicsymbols('z513')
z514 = me.dynamicsymbols('z514')
z518 = me.dynamicsymbols('z518')
z519 = me.dynamicsymbols('z519')
z520 = me.dynamicsymbols('z520')
z521 = me.dynamicsymbols('z521')
z522 = me.dynamicsymbols('z522')
z523 = me.dynamicsymbols('z523')
z524 = me.dynamicsymbols('z524')
z525 = me.dynamicsymbols('z525')
z526 = me.dynamicsymbols('z526')
z527 = me.dynamicsymbols('z527')
z528 = me.dynamicsymbols('z528')
z166 = me.dynamicsymbols('z166')
z161 = me.dynamicsymbols('z161')
z162 = me.dynamicsymbols('z162')
z529 = me.dynamicsymbols('z529')
z530 = me.dynamicsymbols('z530')
z531 = me.dynamicsymbols('z531')
z532 = me.dynamicsymbols('z532')
z533 = me.dynamicsymbols('z533')
z534 = me.dynamicsymbols('z534')
z535 = me.dynamicsymbols('z535')
z536 = me.dynamicsymbols('z536')
z537 = me.dynamicsymbols('z537')
z538 = me.dynamicsymbols('z538')
z539 = me.dynamicsymbols('z539')
z540 = me.dynamicsymbols('z540')
z541 = me.dynamicsymbols('z541')
z542 = me.dynamicsymbols('z542')
z543 = me.dynamicsymbols('z543')
z544 = me.dynamicsymbols('z544')
z545 = me.dynamicsymbols('z545')
z546 = me.dynamicsymbols('z546')
z547 = me.dynamicsymbols('z547')
z548 = me.dynamicsymbols('z548')
z549 = me.dynamicsymbols('z549')
z550 = me.dynamicsymbols('z550')
z551 = me.dynamicsymbols('z551')
z309 = me.dynamicsymbols('z309')
z308 = me.dynamicsymbols('z308')
z310 = me.dynamicsymbols('z310')
z552 = me.dynamicsymbols('z552')
z553 = me.dynamicsymbols('z553')
z554 = me.dynamicsymbols('z554')
z555 = me.dynamicsymbols('z555')
z329 = me.dynamicsymbols('z329')
z330 = me.dynamicsymbols('z330')
z327 = me.dynamicsymbols('z327')
z331 = me.dynamicsymbols('z331')
z328 = me.dynamicsymbols('z328')
z332 = me.dynamicsymbols('z332')
z556 = me.dynamicsymbols('z556')
z557 = me.dynamicsymbols('z557')
z558 = me.dynamicsymbols('z558')
z559 = me.dynamicsymbols('z559')
z560 = me.dynamicsymbols('z560')
z561 = me.dynamicsymbols('z561')
z562 = me.dynamicsymbols('z562')
z563 = me.dynamicsymbols('z563')
z564 = me.dynamicsymbols('z564')
z42 = me.dynamicsymbols('z42')
z46 = me.dynamicsymbols('z46')
z22 = me.dynamicsymbols('z22')
z40 = me.dynamicsymbols('z40')
z372 = me.dynamicsymbols('z372')
z378 = me.dynamicsymbols('z378')
z565 = me.dynamicsymbols('z565')
z566 = me.dynamicsymbols('z566')
z567 = me.dynamicsymbols('z567')
z373 = me.dynamicsymbols('z373')
z379 = me.dynamicsymbols('z379')
z568 = me.dynamicsymbols('z568')
z569 = me.dynamicsymbols('z569')
z570 = me.dynamicsymbols('z570')
z571 = me.dynamicsymbols('z571')
z572 = me.dynamicsymbols('z572')
z573 = me.dynamicsymbols('z573')
z574 = me.dynamicsymbols('z574')
z575 = me.dynamicsymbols('z575')
z576 = me.dynamicsymbols('z576')
z385 = me.dynamicsymbols('z385')
z384 = me.dynamicsymbols('z384')
z386 = me.dynamicsymbols('z386')
z387 = me.dynamicsymbols('z387')
z388 = me.dynamicsymbols('z388')
z577 = me.dynamicsymbols('z577')
z578 = me.dynamicsymbols('z578')
z579 = me.dynamicsymbols('z579')
z30 = me.dynamicsymbols('z30')
z409 = me.dynamicsymbols('z409')
z413 = me.dynamicsymbols('z413')
z580 = me.dynamicsymbols('z580')
z581 = me.dynamicsymbols('z581')
z410 = me.dynamicsymbols('z410')
z414 = me.dynamicsymbols('z414')
z582 = me.dynamicsymbols('z582')
z583 = me.dynamicsymbols('z583')
z584 = me.dynamicsymbols('z584')
z585 = me.dynamicsymbols('z585')
z586 = me.dynamicsymbols('z586')
z587 = me.dynamicsymbols('z587')
z419 = me.dynamicsymbols('z419')
z420 = me.dynamicsymbols('z420')
z421 = me.dynamicsymbols('z421')
z422 = me.dynamicsymbols('z422')
z423 = me.dynamicsymbols('z423')
z424 = me.dynamicsymbols('z424')
z588 = me.dynamicsymbols('z588')
z178 = me.dynamicsymbols('z178')
z589 = me.dynamicsymbols('z589')
z590 = me.dynamicsymbols('z590')
z591 = me.dynamicsymbols('z591')
z592 = me.dynamicsymbols('z592')
z593 = me.dynamicsymbols('z593')
z594 = me.dynamicsymbols('z594')
z595 = me.dynamicsymbols('z595')
z596 = me.dynamicsymbols('z596')
z597 = me.dynamicsymbols('z597')
z598 = me.dynamicsymbols('z598')
z599 = me.dynamicsymbols('z599')
intermediates = [
    (z3, sm.sin(Q4)*sm.sin(Q7) - sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7)),
    (z4, sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4)),
    (z11, (1 - z4**2)**(sm.Rational(1, 2))),
    (z7, sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3)),
    (z14, -sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5)),
    (z61, z14*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + z7*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM)),
    (z1, sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4)),
    (z5, -z1*sm.sin(Q3) + sm.cos(Q3)*sm.cos(Q5)*sm.cos(Q7)),
    (z65, -z5*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z66, RF*sm.cos(Q4)*sm.cos(Q5)/z11),
    (z2, -sm.sin(Q4)*sm.sin(Q5)*sm.sin(Q7) + sm.cos(Q4)*sm.cos(Q7)),
    (z6, -z2*sm.sin(Q3) - sm.sin(Q7)*sm.cos(Q3)*sm.cos(Q5)),
    (z69, -RF*z4*z6/z11),
    (z71, (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)),
    (z9, z2*sm.cos(Q3) - sm.sin(Q3)*sm.sin(Q7)*sm.cos(Q5)),
    (z58, -(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM)),
    (z59, -(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM)),
    (z10, sm.sin(Q3)*sm.sin(Q5) - sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5)),
    (z15, sm.sin(Q3)*sm.cos(Q5) + sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3)),
    (z60, -z10*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) - z15*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)),
    (z62, (CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7)),
    (z63, (CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7)),
    (z8, z1*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q5)*sm.cos(Q7)),
    (z64, z8*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z67, -RF*z4*sm.sin(Q5)*sm.sin(Q7)/z11 + RF*sm.cos(Q4)/z11),
    (z68, -RF*z4*sm.sin(Q7)*sm.cos(Q5)/z11),
    (z70, (RF*z10*z3/z11 - z66*z8)*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))),
    (z72, (z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)),
    (z73, z70*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64) + z71*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z72*(-RF*z3*z7/z11 + z5*z66)),
    (z74, -RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66),
    (z75, z74*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64)),
    (z76, RR*z71*sm.cos(Q3) + RR*z75*sm.sin(Q3) + z73),
    (Q6p, U6),
    (Q7p, U7),
    (z28, Q7p*(CT - RF*sm.tan(LAM))*sm.sin(Q7)*sm.cos(LAM)),
    (z29, -Q7p*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q7)),
    (Q4p, U4),
    (z24, -Q4p*(-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q4) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5)/sm.cos(LAM))),
    (z32, Q4p*z3*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z36, Q4p*RR*sm.cos(Q4) + z24 + z32),
    (z50, Q7p*RF*z4*sm.cos(Q7)/z11 - Q7p*RF*sm.sin(Q4)/z11),
    (z51, Q7p*RF*z4*sm.sin(Q7)/z11 - Q7p*RF*sm.sin(Q5)*sm.cos(Q4)/z11),
    (z54, Q4p*RF*z4**2/z11 - Q4p*RF/z11),
    (z25, Q4p*((CT - RR*sm.tan(LAM) + W)*sm.sin(Q4)*sm.sin(Q5)*sm.cos(LAM) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5)/sm.cos(LAM))),
    (z33, -Q4p*z1*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z37, Q4p*RR*sm.sin(Q4) + z25 + z33),
    (z55, -Q4p*RF*z2*z4/z11),
    (z77, (RF*z10*z3/z11 - z66*z8)*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4)) + (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*(-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))),
    (z78, (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)),
    (z79, z71*(-z14*(z28 + z50) + (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) + (z36 + z54)*sm.sin(Q3)) + z77*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64) + z78*(-RF*z3*z7/z11 + z5*z66)),
    (z80, z75*(-Q6p*RR*z10*sm.sin(Q5) - Q6p*RR*z15*sm.cos(Q5)) - z79),
    (z81, -RR*z80*sm.cos(Q3) + (RR*z75*sm.sin(Q3) + z73)*(-Q6p*RR*z14*sm.cos(Q5) - Q6p*RR*z7*sm.sin(Q5))),
    (U1, z81/z76),
    (z82, RR*z79*sm.sin(Q3) + z73*(-Q6p*RR*z10*sm.sin(Q5) - Q6p*RR*z15*sm.cos(Q5))),
    (z83, z71*(Q6p*RR*z10*sm.sin(Q5) + Q6p*RR*z15*sm.cos(Q5))),
    (z84, RR*z71*(Q6p*RR*z14*sm.cos(Q5) + Q6p*RR*z7*sm.sin(Q5))*sm.sin(Q3) - RR*z83*sm.cos(Q3) + z82),
    (U2, z84/z76),
    (z85, (-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*(-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))),
    (z86, z70*(-z14*(z28 + z50) + (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) + (z36 + z54)*sm.sin(Q3)) + z77*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z85*(-RF*z3*z7/z11 + z5*z66)),
    (z87, z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)),
    (z88, z74*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z87*(-RF*z3*z7/z11 + z5*z66)),
    (z89, -z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4)),
    (z90, z74*(z14*(z28 + z50) - (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) - (z36 + z54)*sm.sin(Q3)) + z89*(-RF*z3*z7/z11 + z5*z66)),
    (z91, RR*z90*sm.sin(Q3) + z86 + z88*(Q6p*RR*z10*sm.sin(Q5) + Q6p*RR*z15*sm.cos(Q5))),
    (z92, RR*z74*sm.sin(Q3) - z70),
    (z93, z74*(-Q6p*RR*z10*sm.sin(Q5) - Q6p*RR*z15*sm.cos(Q5)) - z77),
    (z94, -RR*z93*sm.cos(Q3) + z91 + z92*(-Q6p*RR*z14*sm.cos(Q5) - Q6p*RR*z7*sm.sin(Q5))),
    (U3, z94/z76),
    (z95, (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)),
    (z96, z71*(z14*(z28 + z50) - (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) - (z36 + z54)*sm.sin(Q3)) + z77*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64) + z95*(-RF*z3*z7/z11 + z5*z66)),
    (z97, z75*(-Q6p*RR*z10*sm.sin(Q5) - Q6p*RR*z15*sm.cos(Q5)) + z96),
    (z98, -z71*(Q6p*RR*z14*sm.cos(Q5) + Q6p*RR*z7*sm.sin(Q5)) + z97),
    (U5, z98/z76),
    (z99, (z15*(z28 + z50) + (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) + (z36 + z54)*sm.cos(Q3))*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))),
    (z100, z72*(-z14*(z28 + z50) + (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) + (z36 + z54)*sm.sin(Q3)) + z95*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z99*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64)),
    (z101, z89*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64)),
    (z102, z87*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64)),
    (z103, RR*z101*sm.sin(Q3) + z100 + z102*(Q6p*RR*z10*sm.sin(Q5) + Q6p*RR*z15*sm.cos(Q5))),
    (z104, RR*z95*sm.cos(Q3) + z103 - z72*(-Q6p*RR*z14*sm.cos(Q5) - Q6p*RR*z7*sm.sin(Q5))),
    (U8, z104/z76),
    (z185, (CT - RR*sm.tan(LAM) + W)*sm.sin(Q4)*sm.sin(Q5)*sm.cos(LAM) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5)/sm.cos(LAM)),
    (z186, -z1*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z203, -(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q4)*sm.sin(Q5)),
    (z182, (CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q4) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5)/sm.cos(LAM)),
    (z183, z3*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z184, RF*z4**2/z11 - RF/z11),
    (z187, -RF*z2*z4/z11),
    (z188, -z184*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.cos(Q3) + z187*(-RF*z10*z3/z11 + z66*z8) + (-RF*z10*z3/z11 + z66*z8)*(RR*sm.sin(Q4) + z185 + z186) - (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*(RR*sm.cos(Q4) + z182 + z183)*sm.cos(Q3)),
    (z204, z187*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69) + (RR*sm.sin(Q4) + z185 + z186)*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)),
    (z205, -z184*z71*sm.sin(Q3) + z188*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64) + z204*(-RF*z3*z7/z11 + z5*z66) - z71*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q3)),
    (z207, z205*(-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.cos(Q5))/z76),
    (z252, z1*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) - ((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q4)*sm.cos(Q5)),
    (z255, z205*(-(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))/z76),
    (z256, z205*(-((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q5)*sm.cos(Q7))/z76),
    (z280, z205*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7)/z76),
    (z291, G*MB*z207*sm.cos(Q4) + G*MB*(RR*sm.sin(Q4) + z203) + G*MF*(z255 + z280)*sm.cos(Q4) + G*MF*(RR*sm.sin(Q4) + z185 + z186) + G*MH*(z255 + z256)*sm.cos(Q4) + G*MH*(RR*sm.sin(Q4) + z185 + z252) + G*MR*RR*sm.sin(Q4)),
    (z208, z75*(-RR*z10*sm.sin(Q5) - RR*z15*sm.cos(Q5))),
    (z222, z208 - z71*(RR*z14*sm.cos(Q5) + RR*z7*sm.sin(Q5))),
    (z224, z222*(-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.cos(Q5))/z76),
    (z265, z222*(-(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))/z76),
    (z266, z222*(-((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q5)*sm.cos(Q7))/z76),
    (z286, z222*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7)/z76),
    (z292, G*MB*z224*sm.cos(Q4) + G*MF*(z265 + z286)*sm.cos(Q4) + G*MH*(z265 + z266)*sm.cos(Q4)),
    (z225, (CT - RF*sm.tan(LAM))*sm.sin(Q7)*sm.cos(LAM)),
    (z226, -(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q7)),
    (z227, RF*z4*sm.cos(Q7)/z11 - RF*sm.sin(Q4)/z11),
    (z228, RF*z4*sm.sin(Q7)/z11 - RF*sm.sin(Q5)*sm.cos(Q4)/z11),
    (z229, z225*(-z15*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66) + (RF*z10*z3/z11 - z66*z8)*sm.sin(Q5)*sm.cos(Q4)) + z226*(-(RF*z10*z3/z11 - z66*z8)*sm.sin(Q4) - (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.cos(Q3)*sm.cos(Q4)) + z227*(-z15*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66) + (RF*z10*z3/z11 - z66*z8)*sm.sin(Q5)*sm.cos(Q4)) + z228*(-(RF*z10*z3/z11 - z66*z8)*sm.sin(Q4) - (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.cos(Q3)*sm.cos(Q4))),
    (z243, z225*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q5)*sm.cos(Q4) - z226*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q4) + z227*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q5)*sm.cos(Q4) - z228*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q4)),
    (z244, z14*z225*z71 + z14*z227*z71 - z226*z71*sm.sin(Q3)*sm.cos(Q4) - z228*z71*sm.sin(Q3)*sm.cos(Q4) + z229*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64) + z243*(-RF*z3*z7/z11 + z5*z66)),
    (z246, z244*(-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.cos(Q5))/z76),
    (z273, z244*(-(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))/z76),
    (z274, z244*(-((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q5)*sm.cos(Q7))/z76),
    (z275, -(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q7)),
    (z276, (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q7)),
    (z290, z244*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7)/z76),
    (z293, G*MB*z246*sm.cos(Q4) - G*MF*z225*sm.sin(Q5)*sm.cos(Q4) + G*MF*z226*sm.sin(Q4) + G*MF*(z273 + z290)*sm.cos(Q4) - G*MH*z275*sm.sin(Q5)*sm.cos(Q4) + G*MH*z276*sm.sin(Q4) + G*MH*(z273 + z274)*sm.cos(Q4)),
    (z189, z187*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69) + (RR*sm.sin(Q4) + z185 + z186)*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)),
    (z190, z184*z71*sm.sin(Q3) + z188*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64) + z189*(-RF*z3*z7/z11 + z5*z66) + z71*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q3)),
    (z191, RR*z190*sm.cos(Q3)/z76),
    (z192, -z184*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3) + z187*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3)) + (RR*sm.sin(Q4) + z185 + z186)*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3)) - (RR*sm.cos(Q4) + z182 + z183)*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)),
    (z193, z184*z70*sm.sin(Q3) + z188*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z192*(-RF*z3*z7/z11 + z5*z66) + z70*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q3)),
    (z194, -RR*sm.sin(Q4) - z185 - z186 - z187),
    (z195, -z184*z74*sm.sin(Q3) + z194*(-RF*z3*z7/z11 + z5*z66) - z74*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q3)),
    (z196, RR*z188*sm.cos(Q3) + RR*z195*sm.sin(Q3) + z193),
    (z197, -RR*z196*sm.sin(Q4)*sm.cos(Q3)/z76),
    (z198, z196*(-z10*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)) - z15*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)))/z76),
    (z199, RR*z190*sm.sin(Q3)/z76),
    (z200, -RR*z196*sm.sin(Q3)*sm.sin(Q4)/z76),
    (z201, z196*(z14*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)) + z7*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)))/z76),
    (z202, -(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5)*sm.cos(Q4)),
    (z206, z205*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5))/z76),
    (z247, z196*(-z10*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) - z15*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM))/z76),
    (z248, z196*(-z10*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)) - z8*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)))/z76),
    (z249, z196*(z14*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + z7*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM))/z76),
    (z250, z196*(z5*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) + z7*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)))/z76),
    (z251, -z3*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) - ((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q4)*sm.cos(Q5)),
    (z253, z205*(-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))/z76),
    (z254, z205*(((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q7))/z76),
    (z277, z196*z8*(CT - RF*sm.tan(LAM))*sm.cos(LAM)/z76),
    (z278, -z196*z5*(CT - RF*sm.tan(LAM))*sm.cos(LAM)/z76),
    (z279, z205*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7)/z76),
    (z333, -sm.sin(Q5)*sm.sin(Q6) + sm.cos(Q5)*sm.cos(Q6)),
    (z335, -sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q6) - sm.sin(Q6)*sm.cos(Q4)*sm.cos(Q5)),
    (z336, sm.sin(Q5)*sm.cos(Q6) + sm.sin(Q6)*sm.cos(Q5)),
    (z338, -sm.sin(Q5)*sm.sin(Q6)*sm.cos(Q4) + sm.cos(Q4)*sm.cos(Q5)*sm.cos(Q6)),
    (z425, -sm.sin(Q5)*sm.sin(Q8) + sm.cos(Q5)*sm.cos(Q7)*sm.cos(Q8)),
    (z427, sm.sin(Q5)*sm.cos(Q8) + sm.sin(Q8)*sm.cos(Q5)*sm.cos(Q7)),
    (z430, z3*sm.cos(Q8) - sm.sin(Q8)*sm.cos(Q4)*sm.cos(Q5)),
    (z432, z3*sm.sin(Q8) + sm.cos(Q4)*sm.cos(Q5)*sm.cos(Q8)),
    (z453, z184*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3) + z187*(-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3)) + (RR*sm.sin(Q4) + z185 + z186)*(-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3)) + (RR*sm.cos(Q4) + z182 + z183)*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)),
    (z454, z184*z72*sm.sin(Q3) + z204*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z453*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64) + z72*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q3)),
    (z455, z194*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64)),
    (z456, RR*z204*sm.cos(Q3) + RR*z455*sm.sin(Q3) + z454),
    (z466, z196*((IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5) - (IBXX*sm.cos(LAM)**2 - 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.sin(LAM)**2)*sm.sin(Q5)*sm.cos(Q4))/z76 + (IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5) + (IBXX*sm.cos(LAM)**2 - 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.sin(LAM)**2)*sm.cos(Q5)),
    (z469, IBYY*z196*sm.sin(Q4)/z76 + IBYY*z205/z76),
    (z472, z196*(-(IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q4) + (IBXX*sm.sin(LAM)**2 + 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.cos(LAM)**2)*sm.cos(Q4)*sm.cos(Q5))/z76 + (IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5) + (IBXX*sm.sin(LAM)**2 + 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.cos(LAM)**2)*sm.sin(Q5)),
    (z475, IRXX*z196*z335/z76 + IRXX*z333),
    (z476, IRYY*z196*sm.sin(Q4)/z76 + IRYY*z205/z76),
    (z479, IRXX*z196*z338/z76 + IRXX*z336),
    (z480, z196*(z3*(IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2) + (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5))/z76 + z205*(IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2)*sm.sin(Q7)/z76 + (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5) + (IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2)*sm.cos(Q5)*sm.cos(Q7)),
    (z483, IHYY*z196*z4/z76 + IHYY*z205*sm.cos(Q7)/z76 - IHYY*sm.sin(Q7)*sm.cos(Q5)),
    (z486, z196*(z3*(IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM)) + (IHXX*sm.sin(LAM)**2 + 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.cos(LAM)**2)*sm.cos(Q4)*sm.cos(Q5))/z76 + z205*(IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q7)/z76 + (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)*sm.cos(Q7) + (IHXX*sm.sin(LAM)**2 + 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.cos(LAM)**2)*sm.sin(Q5)),
    (z489, IFXX*z196*z430/z76 + IFXX*z205*sm.sin(Q7)*sm.cos(Q8)/z76 + IFXX*z425),
    (z492, IFYY*z196*z4/z76 + IFYY*z205*sm.cos(Q7)/z76 + IFYY*z456/z76 - IFYY*sm.sin(Q7)*sm.cos(Q5)),
    (z495, IFXX*z196*z432/z76 + IFXX*z205*sm.sin(Q7)*sm.sin(Q8)/z76 + IFXX*z427),
    (z498, -MR*RR**2*sm.sin(Q4)**2 + RR*(-MR*RR*sm.cos(Q4) + MR*(z191 + z197)*sm.sin(Q3) - MR*(z199 + z200)*sm.cos(Q3))*sm.cos(Q4) + z191*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198) + MR*RR*sm.sin(Q3)*sm.cos(Q4) - MR*(z191 + z197)) + z197*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198) + MR*RR*sm.sin(Q3)*sm.cos(Q4) - MR*(z191 + z197)) + z198*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198)) + z199*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201) - MR*RR*sm.cos(Q3)*sm.cos(Q4) - MR*(z199 + z200)) + z200*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201) - MR*RR*sm.cos(Q3)*sm.cos(Q4) - MR*(z199 + z200)) + z201*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201)) + z206*(-MB*z206 - MB*(z191 + z197 + z198)*sm.cos(Q3) - MB*(z199 + z200 + z201)*sm.sin(Q3)) + z207*(-MB*z207 - MB*(RR*sm.sin(Q4) + z203)*sm.cos(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q4) - MB*(z191 + z197 + z198)*sm.sin(Q3)*sm.sin(Q4) + MB*(z199 + z200 + z201)*sm.sin(Q4)*sm.cos(Q3)) + z466*(z196*sm.sin(Q5)*sm.cos(Q4)/z76 - sm.cos(Q5)) + z469*(-z196*sm.sin(Q4)/z76 - z205/z76) + z472*(-z196*sm.cos(Q4)*sm.cos(Q5)/z76 - sm.sin(Q5)) + z475*(-z196*z335/z76 - z333) + z476*(-z196*sm.sin(Q4)/z76 - z205/z76) + z479*(-z196*z338/z76 - z336) + z480*(-z196*z3/z76 - z205*sm.sin(Q7)/z76 - sm.cos(Q5)*sm.cos(Q7)) + z483*(-z196*z4/z76 - z205*sm.cos(Q7)/z76 + sm.sin(Q7)*sm.cos(Q5)) + z486*(-z196*sm.cos(Q4)*sm.cos(Q5)/z76 - sm.sin(Q5)) + z489*(-z196*z430/z76 - z205*sm.sin(Q7)*sm.cos(Q8)/z76 - z425) + z492*(-z196*z4/z76 - z205*sm.cos(Q7)/z76 - z456/z76 + sm.sin(Q7)*sm.cos(Q5)) + z495*(-z196*z432/z76 - z205*sm.sin(Q7)*sm.sin(Q8)/z76 - z427) + (z253 + z254)*(-MH*(z253 + z254) - MH*(z191 + z197 + z247 + z248)*sm.cos(Q3) - MH*(z199 + z200 + z249 + z250)*sm.sin(Q3)) + (z253 + z279)*(-MF*(z253 + z279) - MF*(z191 + z197 + z247 + z277)*sm.cos(Q3) - MF*(z199 + z200 + z249 + z278)*sm.sin(Q3)) + (z255 + z256)*(-MH*(z255 + z256) - MH*(RR*sm.sin(Q4) + z185 + z252)*sm.cos(Q4) + MH*(RR*sm.cos(Q4) + z182 + z251)*sm.sin(Q4) - MH*(z191 + z197 + z247 + z248)*sm.sin(Q3)*sm.sin(Q4) + MH*(z199 + z200 + z249 + z250)*sm.sin(Q4)*sm.cos(Q3)) + (z255 + z280)*(-MF*(z255 + z280) - MF*(RR*sm.sin(Q4) + z185 + z186)*sm.cos(Q4) + MF*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q4) - MF*(z191 + z197 + z247 + z277)*sm.sin(Q3)*sm.sin(Q4) + MF*(z199 + z200 + z249 + z278)*sm.sin(Q4)*sm.cos(Q3)) + (RR*sm.sin(Q4) + z203)*(-MB*z207*sm.cos(Q4) - MB*(RR*sm.sin(Q4) + z203)) + (RR*sm.cos(Q4) + z202)*(MB*z207*sm.sin(Q4) - MB*(RR*sm.cos(Q4) + z202) + MB*(z191 + z197 + z198)*sm.sin(Q3) - MB*(z199 + z200 + z201)*sm.cos(Q3)) + (-MF*(z255 + z280)*sm.cos(Q4) - MF*(RR*sm.sin(Q4) + z185 + z186))*(RR*sm.sin(Q4) + z185 + z186) + (-MH*(z255 + z256)*sm.cos(Q4) - MH*(RR*sm.sin(Q4) + z185 + z252))*(RR*sm.sin(Q4) + z185 + z252) + (RR*sm.cos(Q4) + z182 + z183)*(MF*(z255 + z280)*sm.sin(Q4) - MF*(RR*sm.cos(Q4) + z182 + z183) + MF*(z191 + z197 + z247 + z277)*sm.sin(Q3) - MF*(z199 + z200 + z249 + z278)*sm.cos(Q3)) + (RR*sm.cos(Q4) + z182 + z251)*(MH*(z255 + z256)*sm.sin(Q4) - MH*(RR*sm.cos(Q4) + z182 + z251) + MH*(z191 + z197 + z247 + z248)*sm.sin(Q3) - MH*(z199 + z200 + z249 + z250)*sm.cos(Q3)) + (z191 + z197 + z247 + z248)*(-MH*(z253 + z254)*sm.cos(Q3) - MH*(z255 + z256)*sm.sin(Q3)*sm.sin(Q4) + MH*(RR*sm.cos(Q4) + z182 + z251)*sm.sin(Q3) - MH*(z191 + z197 + z247 + z248)) + (z191 + z197 + z247 + z277)*(-MF*(z253 + z279)*sm.cos(Q3) - MF*(z255 + z280)*sm.sin(Q3)*sm.sin(Q4) + MF*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q3) - MF*(z191 + z197 + z247 + z277)) + (z199 + z200 + z249 + z250)*(-MH*(z253 + z254)*sm.sin(Q3) + MH*(z255 + z256)*sm.sin(Q4)*sm.cos(Q3) - MH*(RR*sm.cos(Q4) + z182 + z251)*sm.cos(Q3) - MH*(z199 + z200 + z249 + z250)) + (z199 + z200 + z249 + z278)*(-MF*(z253 + z279)*sm.sin(Q3) + MF*(z255 + z280)*sm.sin(Q4)*sm.cos(Q3) - MF*(RR*sm.cos(Q4) + z182 + z183)*sm.cos(Q3) - MF*(z199 + z200 + z249 + z278))),
    (z209, -RR*z208*sm.cos(Q3) + (-RR*z14*sm.cos(Q5) - RR*z7*sm.sin(Q5))*(RR*z75*sm.sin(Q3) + z73)),
    (z210, z88*(RR*z10*sm.sin(Q5) + RR*z15*sm.cos(Q5))),
    (z211, z74*(-RR*z10*sm.sin(Q5) - RR*z15*sm.cos(Q5))),
    (z212, -RR*z211*sm.cos(Q3) + z210 + z92*(-RR*z14*sm.cos(Q5) - RR*z7*sm.sin(Q5))),
    (z213, -RR*z212*sm.sin(Q4)*sm.cos(Q3)/z76),
    (z214, z212*(-z10*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)) - z15*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)))/z76),
    (z216, z73*(-RR*z10*sm.sin(Q5) - RR*z15*sm.cos(Q5))),
    (z217, z71*(RR*z10*sm.sin(Q5) + RR*z15*sm.cos(Q5))),
    (z218, -RR*z217*sm.cos(Q3) + RR*z71*(RR*z14*sm.cos(Q5) + RR*z7*sm.sin(Q5))*sm.sin(Q3) + z216),
    (z219, -RR*z212*sm.sin(Q3)*sm.sin(Q4)/z76),
    (z220, z212*(z14*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)) + z7*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)))/z76),
    (z223, z222*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5))/z76),
    (z257, z212*(-z10*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) - z15*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM))/z76),
    (z258, z212*(-z10*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)) - z8*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)))/z76),
    (z259, z209/z76 + z213 + z257 + z258),
    (z260, z212*(z14*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + z7*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM))/z76),
    (z261, z212*(z5*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) + z7*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)))/z76),
    (z262, z218/z76 + z219 + z260 + z261),
    (z263, z222*(-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))/z76),
    (z264, z222*(((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q7))/z76),
    (z281, z212*z8*(CT - RF*sm.tan(LAM))*sm.cos(LAM)/z76),
    (z282, z209/z76 + z213 + z257 + z281),
    (z283, -z212*z5*(CT - RF*sm.tan(LAM))*sm.cos(LAM)/z76),
    (z284, z218/z76 + z219 + z260 + z283),
    (z285, z222*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7)/z76),
    (z467, z212*((IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5) - (IBXX*sm.cos(LAM)**2 - 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.sin(LAM)**2)*sm.sin(Q5)*sm.cos(Q4))/z76),
    (z470, IBYY*z212*sm.sin(Q4)/z76 + IBYY*z222/z76),
    (z473, z212*(-(IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q4) + (IBXX*sm.sin(LAM)**2 + 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.cos(LAM)**2)*sm.cos(Q4)*sm.cos(Q5))/z76),
    (z477, IRYY*z212*sm.sin(Q4)/z76 + IRYY*z222/z76 + IRYY),
    (z481, z212*(z3*(IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2) + (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5))/z76 + z222*(IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2)*sm.sin(Q7)/z76),
    (z484, IHYY*z212*z4/z76 + IHYY*z222*sm.cos(Q7)/z76),
    (z487, z212*(z3*(IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM)) + (IHXX*sm.sin(LAM)**2 + 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.cos(LAM)**2)*sm.cos(Q4)*sm.cos(Q5))/z76 + z222*(IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q7)/z76),
    (z490, IFXX*z212*z430/z76 + IFXX*z222*sm.sin(Q7)*sm.cos(Q8)/z76),
    (z457, z102*(RR*z10*sm.sin(Q5) + RR*z15*sm.cos(Q5))),
    (z458, z457 - z72*(-RR*z14*sm.cos(Q5) - RR*z7*sm.sin(Q5))),
    (z493, IFYY*z212*z4/z76 + IFYY*z222*sm.cos(Q7)/z76 + IFYY*z458/z76),
    (z496, IFXX*z212*z432/z76 + IFXX*z222*sm.sin(Q7)*sm.sin(Q8)/z76),
    (z499, IRXX*z212*z335*(-z196*z335/z76 - z333)/z76 + IRXX*z212*z338*(-z196*z338/z76 - z336)/z76 + z209*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198) + MR*RR*sm.sin(Q3)*sm.cos(Q4) - MR*(z191 + z197))/z76 + z213*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198) + MR*RR*sm.sin(Q3)*sm.cos(Q4) - MR*(z191 + z197)) + z214*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198)) + z218*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201) - MR*RR*sm.cos(Q3)*sm.cos(Q4) - MR*(z199 + z200))/z76 + z219*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201) - MR*RR*sm.cos(Q3)*sm.cos(Q4) - MR*(z199 + z200)) + z220*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201)) + z223*(-MB*z206 - MB*(z191 + z197 + z198)*sm.cos(Q3) - MB*(z199 + z200 + z201)*sm.sin(Q3)) + z224*(-MB*z207 - MB*(RR*sm.sin(Q4) + z203)*sm.cos(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q4) - MB*(z191 + z197 + z198)*sm.sin(Q3)*sm.sin(Q4) + MB*(z199 + z200 + z201)*sm.sin(Q4)*sm.cos(Q3)) + z259*(-MH*(z253 + z254)*sm.cos(Q3) - MH*(z255 + z256)*sm.sin(Q3)*sm.sin(Q4) + MH*(RR*sm.cos(Q4) + z182 + z251)*sm.sin(Q3) - MH*(z191 + z197 + z247 + z248)) + z262*(-MH*(z253 + z254)*sm.sin(Q3) + MH*(z255 + z256)*sm.sin(Q4)*sm.cos(Q3) - MH*(RR*sm.cos(Q4) + z182 + z251)*sm.cos(Q3) - MH*(z199 + z200 + z249 + z250)) + z282*(-MF*(z253 + z279)*sm.cos(Q3) - MF*(z255 + z280)*sm.sin(Q3)*sm.sin(Q4) + MF*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q3) - MF*(z191 + z197 + z247 + z277)) + z284*(-MF*(z253 + z279)*sm.sin(Q3) + MF*(z255 + z280)*sm.sin(Q4)*sm.cos(Q3) - MF*(RR*sm.cos(Q4) + z182 + z183)*sm.cos(Q3) - MF*(z199 + z200 + z249 + z278)) + z467*(z196*sm.sin(Q5)*sm.cos(Q4)/z76 - sm.cos(Q5)) + z470*(-z196*sm.sin(Q4)/z76 - z205/z76) + z473*(-z196*sm.cos(Q4)*sm.cos(Q5)/z76 - sm.sin(Q5)) + z477*(-z196*sm.sin(Q4)/z76 - z205/z76) + z481*(-z196*z3/z76 - z205*sm.sin(Q7)/z76 - sm.cos(Q5)*sm.cos(Q7)) + z484*(-z196*z4/z76 - z205*sm.cos(Q7)/z76 + sm.sin(Q7)*sm.cos(Q5)) + z487*(-z196*sm.cos(Q4)*sm.cos(Q5)/z76 - sm.sin(Q5)) + z490*(-z196*z430/z76 - z205*sm.sin(Q7)*sm.cos(Q8)/z76 - z425) + z493*(-z196*z4/z76 - z205*sm.cos(Q7)/z76 - z456/z76 + sm.sin(Q7)*sm.cos(Q5)) + z496*(-z196*z432/z76 - z205*sm.sin(Q7)*sm.sin(Q8)/z76 - z427) + (z263 + z264)*(-MH*(z253 + z254) - MH*(z191 + z197 + z247 + z248)*sm.cos(Q3) - MH*(z199 + z200 + z249 + z250)*sm.sin(Q3)) + (z263 + z285)*(-MF*(z253 + z279) - MF*(z191 + z197 + z247 + z277)*sm.cos(Q3) - MF*(z199 + z200 + z249 + z278)*sm.sin(Q3)) + (z265 + z266)*(-MH*(z255 + z256) - MH*(RR*sm.sin(Q4) + z185 + z252)*sm.cos(Q4) + MH*(RR*sm.cos(Q4) + z182 + z251)*sm.sin(Q4) - MH*(z191 + z197 + z247 + z248)*sm.sin(Q3)*sm.sin(Q4) + MH*(z199 + z200 + z249 + z250)*sm.sin(Q4)*sm.cos(Q3)) + (z265 + z286)*(-MF*(z255 + z280) - MF*(RR*sm.sin(Q4) + z185 + z186)*sm.cos(Q4) + MF*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q4) - MF*(z191 + z197 + z247 + z277)*sm.sin(Q3)*sm.sin(Q4) + MF*(z199 + z200 + z249 + z278)*sm.sin(Q4)*sm.cos(Q3))),
    (z230, z225*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.sin(Q5)*sm.cos(Q4) - z226*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.sin(Q4) + z227*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.sin(Q5)*sm.cos(Q4) - z228*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.sin(Q4)),
    (z231, -z14*z225*z71 - z14*z227*z71 + z226*z71*sm.sin(Q3)*sm.cos(Q4) + z228*z71*sm.sin(Q3)*sm.cos(Q4) + z229*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64) + z230*(-RF*z3*z7/z11 + z5*z66)),
    (z232, RR*z231*sm.cos(Q3)/z76),
    (z233, z225*(-z15*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)) + z226*(-(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)*sm.cos(Q4) - (-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4)) + z227*(-z15*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)) + z228*(-(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)*sm.cos(Q4) - (-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4))),
    (z234, -z14*z225*z70 - z14*z227*z70 + z226*z70*sm.sin(Q3)*sm.cos(Q4) + z228*z70*sm.sin(Q3)*sm.cos(Q4) + z229*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z233*(-RF*z3*z7/z11 + z5*z66)),
    (z235, z225*sm.sin(Q5)*sm.cos(Q4) - z226*sm.sin(Q4) + z227*sm.sin(Q5)*sm.cos(Q4) - z228*sm.sin(Q4)),
    (z236, z14*z225*z74 + z14*z227*z74 - z226*z74*sm.sin(Q3)*sm.cos(Q4) - z228*z74*sm.sin(Q3)*sm.cos(Q4) + z235*(-RF*z3*z7/z11 + z5*z66)),
    (z237, RR*z229*sm.cos(Q3) + RR*z236*sm.sin(Q3) + z234),
    (z238, -RR*z237*sm.sin(Q4)*sm.cos(Q3)/z76),
    (z239, z237*(-z10*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)) - z15*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)))/z76),
    (z240, RR*z231*sm.sin(Q3)/z76),
    (z241, -RR*z237*sm.sin(Q3)*sm.sin(Q4)/z76),
    (z242, z237*(z14*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)) + z7*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)))/z76),
    (z245, z244*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5))/z76),
    (z267, z237*(-z10*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) - z15*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM))/z76),
    (z268, z237*(-z10*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)) - z8*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)))/z76),
    (z269, z237*(z14*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + z7*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM))/z76),
    (z270, z237*(z5*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) + z7*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)))/z76),
    (z271, z244*(-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))/z76),
    (z272, z244*(((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q7))/z76),
    (z287, z237*z8*(CT - RF*sm.tan(LAM))*sm.cos(LAM)/z76),
    (z288, -z237*z5*(CT - RF*sm.tan(LAM))*sm.cos(LAM)/z76),
    (z289, z244*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7)/z76),
    (z468, z237*((IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5) - (IBXX*sm.cos(LAM)**2 - 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.sin(LAM)**2)*sm.sin(Q5)*sm.cos(Q4))/z76),
    (z471, IBYY*z237*sm.sin(Q4)/z76 + IBYY*z244/z76),
    (z474, z237*(-(IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q4) + (IBXX*sm.sin(LAM)**2 + 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.cos(LAM)**2)*sm.cos(Q4)*sm.cos(Q5))/z76),
    (z478, IRYY*z237*sm.sin(Q4)/z76 + IRYY*z244/z76),
    (z482, IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + z237*(z3*(IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2) + (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5))/z76 + z244*(IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2)*sm.sin(Q7)/z76 + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM)),
    (z485, IHYY*z237*z4/z76 + IHYY*z244*sm.cos(Q7)/z76),
    (z488, IHXX*sm.sin(LAM)**2 + 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.cos(LAM)**2 + z237*(z3*(IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM)) + (IHXX*sm.sin(LAM)**2 + 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.cos(LAM)**2)*sm.cos(Q4)*sm.cos(Q5))/z76 + z244*(IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q7)/z76),
    (z491, IFXX*z237*z430/z76 + IFXX*z244*sm.sin(Q7)*sm.cos(Q8)/z76 - IFXX*sm.sin(Q8)),
    (z459, z225*(z15*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)) + z226*((z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)*sm.cos(Q4) - (z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4)) + z227*(z15*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)) + z228*((z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)*sm.cos(Q4) - (z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4))),
    (z460, -z14*z225*z72 - z14*z227*z72 + z226*z72*sm.sin(Q3)*sm.cos(Q4) + z228*z72*sm.sin(Q3)*sm.cos(Q4) + z243*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z459*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64)),
    (z461, z235*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64)),
    (z462, RR*z243*sm.cos(Q3) + RR*z461*sm.sin(Q3) + z460),
    (z494, IFYY*z237*z4/z76 + IFYY*z244*sm.cos(Q7)/z76 + IFYY*z462/z76),
    (z497, IFXX*z237*z432/z76 + IFXX*z244*sm.sin(Q7)*sm.sin(Q8)/z76 + IFXX*sm.cos(Q8)),
    (z500, IRXX*z237*z335*(-z196*z335/z76 - z333)/z76 + IRXX*z237*z338*(-z196*z338/z76 - z336)/z76 + z225*(-MF*z14*(z191 + z197 + z247 + z277) - MF*z15*(z199 + z200 + z249 + z278) - MF*(z253 + z279)*sm.cos(Q5) + MF*(z255 + z280)*sm.sin(Q5) + MF*(RR*sm.sin(Q4) + z185 + z186)*sm.sin(Q5)*sm.cos(Q4) - MF*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q4)*sm.sin(Q5)) + z226*(-MF*(RR*sm.sin(Q4) + z185 + z186)*sm.sin(Q4) - MF*(RR*sm.cos(Q4) + z182 + z183)*sm.cos(Q4) + MF*(z191 + z197 + z247 + z277)*sm.sin(Q3)*sm.cos(Q4) - MF*(z199 + z200 + z249 + z278)*sm.cos(Q3)*sm.cos(Q4)) + z232*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198) + MR*RR*sm.sin(Q3)*sm.cos(Q4) - MR*(z191 + z197)) + z238*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198) + MR*RR*sm.sin(Q3)*sm.cos(Q4) - MR*(z191 + z197)) + z239*(-MB*z206*sm.cos(Q3) - MB*z207*sm.sin(Q3)*sm.sin(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q3) - MB*(z191 + z197 + z198)) + z240*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201) - MR*RR*sm.cos(Q3)*sm.cos(Q4) - MR*(z199 + z200)) + z241*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201) - MR*RR*sm.cos(Q3)*sm.cos(Q4) - MR*(z199 + z200)) + z242*(-MB*z206*sm.sin(Q3) + MB*z207*sm.sin(Q4)*sm.cos(Q3) - MB*(RR*sm.cos(Q4) + z202)*sm.cos(Q3) - MB*(z199 + z200 + z201)) + z245*(-MB*z206 - MB*(z191 + z197 + z198)*sm.cos(Q3) - MB*(z199 + z200 + z201)*sm.sin(Q3)) + z246*(-MB*z207 - MB*(RR*sm.sin(Q4) + z203)*sm.cos(Q4) + MB*(RR*sm.cos(Q4) + z202)*sm.sin(Q4) - MB*(z191 + z197 + z198)*sm.sin(Q3)*sm.sin(Q4) + MB*(z199 + z200 + z201)*sm.sin(Q4)*sm.cos(Q3)) + z275*(-MH*z14*(z191 + z197 + z247 + z248) - MH*z15*(z199 + z200 + z249 + z250) - MH*(z253 + z254)*sm.cos(Q5) + MH*(z255 + z256)*sm.sin(Q5) + MH*(RR*sm.sin(Q4) + z185 + z252)*sm.sin(Q5)*sm.cos(Q4) - MH*(RR*sm.cos(Q4) + z182 + z251)*sm.sin(Q4)*sm.sin(Q5)) + z276*(-MH*(RR*sm.sin(Q4) + z185 + z252)*sm.sin(Q4) - MH*(RR*sm.cos(Q4) + z182 + z251)*sm.cos(Q4) + MH*(z191 + z197 + z247 + z248)*sm.sin(Q3)*sm.cos(Q4) - MH*(z199 + z200 + z249 + z250)*sm.cos(Q3)*sm.cos(Q4)) + z468*(z196*sm.sin(Q5)*sm.cos(Q4)/z76 - sm.cos(Q5)) + z471*(-z196*sm.sin(Q4)/z76 - z205/z76) + z474*(-z196*sm.cos(Q4)*sm.cos(Q5)/z76 - sm.sin(Q5)) + z478*(-z196*sm.sin(Q4)/z76 - z205/z76) + z482*(-z196*z3/z76 - z205*sm.sin(Q7)/z76 - sm.cos(Q5)*sm.cos(Q7)) + z485*(-z196*z4/z76 - z205*sm.cos(Q7)/z76 + sm.sin(Q7)*sm.cos(Q5)) + z488*(-z196*sm.cos(Q4)*sm.cos(Q5)/z76 - sm.sin(Q5)) + z491*(-z196*z430/z76 - z205*sm.sin(Q7)*sm.cos(Q8)/z76 - z425) + z494*(-z196*z4/z76 - z205*sm.cos(Q7)/z76 - z456/z76 + sm.sin(Q7)*sm.cos(Q5)) + z497*(-z196*z432/z76 - z205*sm.sin(Q7)*sm.sin(Q8)/z76 - z427) + (z271 + z272)*(-MH*(z253 + z254) - MH*(z191 + z197 + z247 + z248)*sm.cos(Q3) - MH*(z199 + z200 + z249 + z250)*sm.sin(Q3)) + (z271 + z289)*(-MF*(z253 + z279) - MF*(z191 + z197 + z247 + z277)*sm.cos(Q3) - MF*(z199 + z200 + z249 + z278)*sm.sin(Q3)) + (z273 + z274)*(-MH*(z255 + z256) - MH*(RR*sm.sin(Q4) + z185 + z252)*sm.cos(Q4) + MH*(RR*sm.cos(Q4) + z182 + z251)*sm.sin(Q4) - MH*(z191 + z197 + z247 + z248)*sm.sin(Q3)*sm.sin(Q4) + MH*(z199 + z200 + z249 + z250)*sm.sin(Q4)*sm.cos(Q3)) + (z273 + z290)*(-MF*(z255 + z280) - MF*(RR*sm.sin(Q4) + z185 + z186)*sm.cos(Q4) + MF*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q4) - MF*(z191 + z197 + z247 + z277)*sm.sin(Q3)*sm.sin(Q4) + MF*(z199 + z200 + z249 + z278)*sm.sin(Q4)*sm.cos(Q3)) + (z232 + z238 + z267 + z268)*(-MH*(z253 + z254)*sm.cos(Q3) - MH*(z255 + z256)*sm.sin(Q3)*sm.sin(Q4) + MH*(RR*sm.cos(Q4) + z182 + z251)*sm.sin(Q3) - MH*(z191 + z197 + z247 + z248)) + (z232 + z238 + z267 + z287)*(-MF*(z253 + z279)*sm.cos(Q3) - MF*(z255 + z280)*sm.sin(Q3)*sm.sin(Q4) + MF*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q3) - MF*(z191 + z197 + z247 + z277)) + (z240 + z241 + z269 + z270)*(-MH*(z253 + z254)*sm.sin(Q3) + MH*(z255 + z256)*sm.sin(Q4)*sm.cos(Q3) - MH*(RR*sm.cos(Q4) + z182 + z251)*sm.cos(Q3) - MH*(z199 + z200 + z249 + z250)) + (z240 + z241 + z269 + z288)*(-MF*(z253 + z279)*sm.sin(Q3) + MF*(z255 + z280)*sm.sin(Q4)*sm.cos(Q3) - MF*(RR*sm.cos(Q4) + z182 + z183)*sm.cos(Q3) - MF*(z199 + z200 + z249 + z278))),
    (z215, z209/z76 + z213 + z214),
    (z221, z218/z76 + z219 + z220),
    (z501, -MB*z224*(RR*sm.sin(Q4) + z203)*sm.cos(Q4) - MF*(z265 + z286)*(RR*sm.sin(Q4) + z185 + z186)*sm.cos(Q4) - MH*(z265 + z266)*(RR*sm.sin(Q4) + z185 + z252)*sm.cos(Q4) + RR*(MR*(z209/z76 + z213)*sm.sin(Q3) - MR*(z218/z76 + z219)*sm.cos(Q3))*sm.cos(Q4) + z191*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4) - MR*(z209/z76 + z213)) + z197*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4) - MR*(z209/z76 + z213)) + z198*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4)) + z199*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3) - MR*(z218/z76 + z219)) + z200*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3) - MR*(z218/z76 + z219)) + z201*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3)) + z206*(-MB*z215*sm.cos(Q3) - MB*z221*sm.sin(Q3) - MB*z223) + z207*(-MB*z215*sm.sin(Q3)*sm.sin(Q4) + MB*z221*sm.sin(Q4)*sm.cos(Q3) - MB*z224) - z212*z335*z475/z76 - z212*z338*z479/z76 + z212*z466*sm.sin(Q5)*sm.cos(Q4)/z76 - z212*z472*sm.cos(Q4)*sm.cos(Q5)/z76 - z212*z486*sm.cos(Q4)*sm.cos(Q5)/z76 + z469*(-z212*sm.sin(Q4)/z76 - z222/z76) + z476*(-z212*sm.sin(Q4)/z76 - z222/z76 - 1) + z480*(-z212*z3/z76 - z222*sm.sin(Q7)/z76) + z483*(-z212*z4/z76 - z222*sm.cos(Q7)/z76) + z489*(-z212*z430/z76 - z222*sm.sin(Q7)*sm.cos(Q8)/z76) + z492*(-z212*z4/z76 - z222*sm.cos(Q7)/z76 - z458/z76) + z495*(-z212*z432/z76 - z222*sm.sin(Q7)*sm.sin(Q8)/z76) + (z253 + z254)*(-MH*z259*sm.cos(Q3) - MH*z262*sm.sin(Q3) - MH*(z263 + z264)) + (z253 + z279)*(-MF*z282*sm.cos(Q3) - MF*z284*sm.sin(Q3) - MF*(z263 + z285)) + (z255 + z256)*(-MH*z259*sm.sin(Q3)*sm.sin(Q4) + MH*z262*sm.sin(Q4)*sm.cos(Q3) - MH*(z265 + z266)) + (z255 + z280)*(-MF*z282*sm.sin(Q3)*sm.sin(Q4) + MF*z284*sm.sin(Q4)*sm.cos(Q3) - MF*(z265 + z286)) + (RR*sm.cos(Q4) + z202)*(MB*z215*sm.sin(Q3) - MB*z221*sm.cos(Q3) + MB*z224*sm.sin(Q4)) + (-MF*z282 - MF*(z263 + z285)*sm.cos(Q3) - MF*(z265 + z286)*sm.sin(Q3)*sm.sin(Q4))*(z191 + z197 + z247 + z277) + (-MF*z284 - MF*(z263 + z285)*sm.sin(Q3) + MF*(z265 + z286)*sm.sin(Q4)*sm.cos(Q3))*(z199 + z200 + z249 + z278) + (-MH*z259 - MH*(z263 + z264)*sm.cos(Q3) - MH*(z265 + z266)*sm.sin(Q3)*sm.sin(Q4))*(z191 + z197 + z247 + z248) + (-MH*z262 - MH*(z263 + z264)*sm.sin(Q3) + MH*(z265 + z266)*sm.sin(Q4)*sm.cos(Q3))*(z199 + z200 + z249 + z250) + (RR*sm.cos(Q4) + z182 + z183)*(MF*z282*sm.sin(Q3) - MF*z284*sm.cos(Q3) + MF*(z265 + z286)*sm.sin(Q4)) + (RR*sm.cos(Q4) + z182 + z251)*(MH*z259*sm.sin(Q3) - MH*z262*sm.cos(Q3) + MH*(z265 + z266)*sm.sin(Q4))),
    (z502, -IRXX*z212**2*z335**2/z76**2 - IRXX*z212**2*z338**2/z76**2 + z209*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4) - MR*(z209/z76 + z213))/z76 + z212*z467*sm.sin(Q5)*sm.cos(Q4)/z76 - z212*z473*sm.cos(Q4)*sm.cos(Q5)/z76 - z212*z487*sm.cos(Q4)*sm.cos(Q5)/z76 + z213*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4) - MR*(z209/z76 + z213)) + z214*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4)) + z218*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3) - MR*(z218/z76 + z219))/z76 + z219*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3) - MR*(z218/z76 + z219)) + z220*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3)) + z223*(-MB*z215*sm.cos(Q3) - MB*z221*sm.sin(Q3) - MB*z223) + z224*(-MB*z215*sm.sin(Q3)*sm.sin(Q4) + MB*z221*sm.sin(Q4)*sm.cos(Q3) - MB*z224) + z259*(-MH*z259 - MH*(z263 + z264)*sm.cos(Q3) - MH*(z265 + z266)*sm.sin(Q3)*sm.sin(Q4)) + z262*(-MH*z262 - MH*(z263 + z264)*sm.sin(Q3) + MH*(z265 + z266)*sm.sin(Q4)*sm.cos(Q3)) + z282*(-MF*z282 - MF*(z263 + z285)*sm.cos(Q3) - MF*(z265 + z286)*sm.sin(Q3)*sm.sin(Q4)) + z284*(-MF*z284 - MF*(z263 + z285)*sm.sin(Q3) + MF*(z265 + z286)*sm.sin(Q4)*sm.cos(Q3)) + z470*(-z212*sm.sin(Q4)/z76 - z222/z76) + z477*(-z212*sm.sin(Q4)/z76 - z222/z76 - 1) + z481*(-z212*z3/z76 - z222*sm.sin(Q7)/z76) + z484*(-z212*z4/z76 - z222*sm.cos(Q7)/z76) + z490*(-z212*z430/z76 - z222*sm.sin(Q7)*sm.cos(Q8)/z76) + z493*(-z212*z4/z76 - z222*sm.cos(Q7)/z76 - z458/z76) + z496*(-z212*z432/z76 - z222*sm.sin(Q7)*sm.sin(Q8)/z76) + (z263 + z264)*(-MH*z259*sm.cos(Q3) - MH*z262*sm.sin(Q3) - MH*(z263 + z264)) + (z263 + z285)*(-MF*z282*sm.cos(Q3) - MF*z284*sm.sin(Q3) - MF*(z263 + z285)) + (z265 + z266)*(-MH*z259*sm.sin(Q3)*sm.sin(Q4) + MH*z262*sm.sin(Q4)*sm.cos(Q3) - MH*(z265 + z266)) + (z265 + z286)*(-MF*z282*sm.sin(Q3)*sm.sin(Q4) + MF*z284*sm.sin(Q4)*sm.cos(Q3) - MF*(z265 + z286))),
    (z503, -IRXX*z335**2*z212*z237/z76**2 - IRXX*z338**2*z212*z237/z76**2 + z212*z468*sm.sin(Q5)*sm.cos(Q4)/z76 - z212*z474*sm.cos(Q4)*sm.cos(Q5)/z76 - z212*z488*sm.cos(Q4)*sm.cos(Q5)/z76 + z225*(-MF*z14*z282 - MF*z15*z284 - MF*(z263 + z285)*sm.cos(Q5) + MF*(z265 + z286)*sm.sin(Q5)) + z226*(MF*z282*sm.sin(Q3)*sm.cos(Q4) - MF*z284*sm.cos(Q3)*sm.cos(Q4)) + z232*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4) - MR*(z209/z76 + z213)) + z238*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4) - MR*(z209/z76 + z213)) + z239*(-MB*z215 - MB*z223*sm.cos(Q3) - MB*z224*sm.sin(Q3)*sm.sin(Q4)) + z240*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3) - MR*(z218/z76 + z219)) + z241*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3) - MR*(z218/z76 + z219)) + z242*(-MB*z221 - MB*z223*sm.sin(Q3) + MB*z224*sm.sin(Q4)*sm.cos(Q3)) + z245*(-MB*z215*sm.cos(Q3) - MB*z221*sm.sin(Q3) - MB*z223) + z246*(-MB*z215*sm.sin(Q3)*sm.sin(Q4) + MB*z221*sm.sin(Q4)*sm.cos(Q3) - MB*z224) + z275*(-MH*z14*z259 - MH*z15*z262 - MH*(z263 + z264)*sm.cos(Q5) + MH*(z265 + z266)*sm.sin(Q5)) + z276*(MH*z259*sm.sin(Q3)*sm.cos(Q4) - MH*z262*sm.cos(Q3)*sm.cos(Q4)) + z471*(-z212*sm.sin(Q4)/z76 - z222/z76) + z478*(-z212*sm.sin(Q4)/z76 - z222/z76 - 1) + z482*(-z212*z3/z76 - z222*sm.sin(Q7)/z76) + z485*(-z212*z4/z76 - z222*sm.cos(Q7)/z76) + z491*(-z212*z430/z76 - z222*sm.sin(Q7)*sm.cos(Q8)/z76) + z494*(-z212*z4/z76 - z222*sm.cos(Q7)/z76 - z458/z76) + z497*(-z212*z432/z76 - z222*sm.sin(Q7)*sm.sin(Q8)/z76) + (z271 + z272)*(-MH*z259*sm.cos(Q3) - MH*z262*sm.sin(Q3) - MH*(z263 + z264)) + (z271 + z289)*(-MF*z282*sm.cos(Q3) - MF*z284*sm.sin(Q3) - MF*(z263 + z285)) + (z273 + z274)*(-MH*z259*sm.sin(Q3)*sm.sin(Q4) + MH*z262*sm.sin(Q4)*sm.cos(Q3) - MH*(z265 + z266)) + (z273 + z290)*(-MF*z282*sm.sin(Q3)*sm.sin(Q4) + MF*z284*sm.sin(Q4)*sm.cos(Q3) - MF*(z265 + z286)) + (-MF*z282 - MF*(z263 + z285)*sm.cos(Q3) - MF*(z265 + z286)*sm.sin(Q3)*sm.sin(Q4))*(z232 + z238 + z267 + z287) + (-MF*z284 - MF*(z263 + z285)*sm.sin(Q3) + MF*(z265 + z286)*sm.sin(Q4)*sm.cos(Q3))*(z240 + z241 + z269 + z288) + (-MH*z259 - MH*(z263 + z264)*sm.cos(Q3) - MH*(z265 + z266)*sm.sin(Q3)*sm.sin(Q4))*(z232 + z238 + z267 + z268) + (-MH*z262 - MH*(z263 + z264)*sm.sin(Q3) + MH*(z265 + z266)*sm.sin(Q4)*sm.cos(Q3))*(z240 + z241 + z269 + z270)),
    (z504, -MB*z246*(RR*sm.sin(Q4) + z203)*sm.cos(Q4) + RR*(MR*(z232 + z238)*sm.sin(Q3) - MR*(z240 + z241)*sm.cos(Q3))*sm.cos(Q4) + z191*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239) - MR*(z232 + z238)) + z197*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239) - MR*(z232 + z238)) + z198*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239)) + z199*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242) - MR*(z240 + z241)) + z200*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242) - MR*(z240 + z241)) + z201*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242)) + z206*(-MB*z245 - MB*(z232 + z238 + z239)*sm.cos(Q3) - MB*(z240 + z241 + z242)*sm.sin(Q3)) + z207*(-MB*z246 - MB*(z232 + z238 + z239)*sm.sin(Q3)*sm.sin(Q4) + MB*(z240 + z241 + z242)*sm.sin(Q4)*sm.cos(Q3)) - z237*z335*z475/z76 - z237*z338*z479/z76 + z237*z466*sm.sin(Q5)*sm.cos(Q4)/z76 - z237*z472*sm.cos(Q4)*sm.cos(Q5)/z76 + z469*(-z237*sm.sin(Q4)/z76 - z244/z76) + z476*(-z237*sm.sin(Q4)/z76 - z244/z76) + z480*(-z237*z3/z76 - z244*sm.sin(Q7)/z76) + z483*(-z237*z4/z76 - z244*sm.cos(Q7)/z76) + z486*(-z237*sm.cos(Q4)*sm.cos(Q5)/z76 - 1) + z489*(-z237*z430/z76 - z244*sm.sin(Q7)*sm.cos(Q8)/z76 + sm.sin(Q8)) + z492*(-z237*z4/z76 - z244*sm.cos(Q7)/z76 - z462/z76) + z495*(-z237*z432/z76 - z244*sm.sin(Q7)*sm.sin(Q8)/z76 - sm.cos(Q8)) + (z253 + z254)*(-MH*z275*sm.cos(Q5) - MH*(z271 + z272) - MH*(z232 + z238 + z267 + z268)*sm.cos(Q3) - MH*(z240 + z241 + z269 + z270)*sm.sin(Q3)) + (z253 + z279)*(-MF*z225*sm.cos(Q5) - MF*(z271 + z289) - MF*(z232 + z238 + z267 + z287)*sm.cos(Q3) - MF*(z240 + z241 + z269 + z288)*sm.sin(Q3)) + (z255 + z256)*(MH*z275*sm.sin(Q5) - MH*(z273 + z274) - MH*(z232 + z238 + z267 + z268)*sm.sin(Q3)*sm.sin(Q4) + MH*(z240 + z241 + z269 + z270)*sm.sin(Q4)*sm.cos(Q3)) + (z255 + z280)*(MF*z225*sm.sin(Q5) - MF*(z273 + z290) - MF*(z232 + z238 + z267 + z287)*sm.sin(Q3)*sm.sin(Q4) + MF*(z240 + z241 + z269 + z288)*sm.sin(Q4)*sm.cos(Q3)) + (RR*sm.cos(Q4) + z202)*(MB*z246*sm.sin(Q4) + MB*(z232 + z238 + z239)*sm.sin(Q3) - MB*(z240 + z241 + z242)*sm.cos(Q3)) + (RR*sm.sin(Q4) + z185 + z186)*(MF*z225*sm.sin(Q5)*sm.cos(Q4) - MF*z226*sm.sin(Q4) - MF*(z273 + z290)*sm.cos(Q4)) + (RR*sm.sin(Q4) + z185 + z252)*(MH*z275*sm.sin(Q5)*sm.cos(Q4) - MH*z276*sm.sin(Q4) - MH*(z273 + z274)*sm.cos(Q4)) + (RR*sm.cos(Q4) + z182 + z183)*(-MF*z225*sm.sin(Q4)*sm.sin(Q5) - MF*z226*sm.cos(Q4) + MF*(z273 + z290)*sm.sin(Q4) + MF*(z232 + z238 + z267 + z287)*sm.sin(Q3) - MF*(z240 + z241 + z269 + z288)*sm.cos(Q3)) + (RR*sm.cos(Q4) + z182 + z251)*(-MH*z275*sm.sin(Q4)*sm.sin(Q5) - MH*z276*sm.cos(Q4) + MH*(z273 + z274)*sm.sin(Q4) + MH*(z232 + z238 + z267 + z268)*sm.sin(Q3) - MH*(z240 + z241 + z269 + z270)*sm.cos(Q3)) + (z191 + z197 + z247 + z248)*(-MH*z14*z275 + MH*z276*sm.sin(Q3)*sm.cos(Q4) - MH*(z271 + z272)*sm.cos(Q3) - MH*(z273 + z274)*sm.sin(Q3)*sm.sin(Q4) - MH*(z232 + z238 + z267 + z268)) + (z191 + z197 + z247 + z277)*(-MF*z14*z225 + MF*z226*sm.sin(Q3)*sm.cos(Q4) - MF*(z271 + z289)*sm.cos(Q3) - MF*(z273 + z290)*sm.sin(Q3)*sm.sin(Q4) - MF*(z232 + z238 + z267 + z287)) + (z199 + z200 + z249 + z250)*(-MH*z15*z275 - MH*z276*sm.cos(Q3)*sm.cos(Q4) - MH*(z271 + z272)*sm.sin(Q3) + MH*(z273 + z274)*sm.sin(Q4)*sm.cos(Q3) - MH*(z240 + z241 + z269 + z270)) + (z199 + z200 + z249 + z278)*(-MF*z15*z225 - MF*z226*sm.cos(Q3)*sm.cos(Q4) - MF*(z271 + z289)*sm.sin(Q3) + MF*(z273 + z290)*sm.sin(Q4)*sm.cos(Q3) - MF*(z240 + z241 + z269 + z288))),
    (z505, -IRXX*z335**2*z212*z237/z76**2 - IRXX*z338**2*z212*z237/z76**2 + z209*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239) - MR*(z232 + z238))/z76 + z213*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239) - MR*(z232 + z238)) + z214*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239)) + z218*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242) - MR*(z240 + z241))/z76 + z219*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242) - MR*(z240 + z241)) + z220*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242)) + z223*(-MB*z245 - MB*(z232 + z238 + z239)*sm.cos(Q3) - MB*(z240 + z241 + z242)*sm.sin(Q3)) + z224*(-MB*z246 - MB*(z232 + z238 + z239)*sm.sin(Q3)*sm.sin(Q4) + MB*(z240 + z241 + z242)*sm.sin(Q4)*sm.cos(Q3)) + z237*z467*sm.sin(Q5)*sm.cos(Q4)/z76 - z237*z473*sm.cos(Q4)*sm.cos(Q5)/z76 + z259*(-MH*z14*z275 + MH*z276*sm.sin(Q3)*sm.cos(Q4) - MH*(z271 + z272)*sm.cos(Q3) - MH*(z273 + z274)*sm.sin(Q3)*sm.sin(Q4) - MH*(z232 + z238 + z267 + z268)) + z262*(-MH*z15*z275 - MH*z276*sm.cos(Q3)*sm.cos(Q4) - MH*(z271 + z272)*sm.sin(Q3) + MH*(z273 + z274)*sm.sin(Q4)*sm.cos(Q3) - MH*(z240 + z241 + z269 + z270)) + z282*(-MF*z14*z225 + MF*z226*sm.sin(Q3)*sm.cos(Q4) - MF*(z271 + z289)*sm.cos(Q3) - MF*(z273 + z290)*sm.sin(Q3)*sm.sin(Q4) - MF*(z232 + z238 + z267 + z287)) + z284*(-MF*z15*z225 - MF*z226*sm.cos(Q3)*sm.cos(Q4) - MF*(z271 + z289)*sm.sin(Q3) + MF*(z273 + z290)*sm.sin(Q4)*sm.cos(Q3) - MF*(z240 + z241 + z269 + z288)) + z470*(-z237*sm.sin(Q4)/z76 - z244/z76) + z477*(-z237*sm.sin(Q4)/z76 - z244/z76) + z481*(-z237*z3/z76 - z244*sm.sin(Q7)/z76) + z484*(-z237*z4/z76 - z244*sm.cos(Q7)/z76) + z487*(-z237*sm.cos(Q4)*sm.cos(Q5)/z76 - 1) + z490*(-z237*z430/z76 - z244*sm.sin(Q7)*sm.cos(Q8)/z76 + sm.sin(Q8)) + z493*(-z237*z4/z76 - z244*sm.cos(Q7)/z76 - z462/z76) + z496*(-z237*z432/z76 - z244*sm.sin(Q7)*sm.sin(Q8)/z76 - sm.cos(Q8)) + (z263 + z264)*(-MH*z275*sm.cos(Q5) - MH*(z271 + z272) - MH*(z232 + z238 + z267 + z268)*sm.cos(Q3) - MH*(z240 + z241 + z269 + z270)*sm.sin(Q3)) + (z263 + z285)*(-MF*z225*sm.cos(Q5) - MF*(z271 + z289) - MF*(z232 + z238 + z267 + z287)*sm.cos(Q3) - MF*(z240 + z241 + z269 + z288)*sm.sin(Q3)) + (z265 + z266)*(MH*z275*sm.sin(Q5) - MH*(z273 + z274) - MH*(z232 + z238 + z267 + z268)*sm.sin(Q3)*sm.sin(Q4) + MH*(z240 + z241 + z269 + z270)*sm.sin(Q4)*sm.cos(Q3)) + (z265 + z286)*(MF*z225*sm.sin(Q5) - MF*(z273 + z290) - MF*(z232 + z238 + z267 + z287)*sm.sin(Q3)*sm.sin(Q4) + MF*(z240 + z241 + z269 + z288)*sm.sin(Q4)*sm.cos(Q3))),
    (z506, -IRXX*z237**2*z335**2/z76**2 - IRXX*z237**2*z338**2/z76**2 + z225*(-MF*z14*(z232 + z238 + z267 + z287) - MF*z15*(z240 + z241 + z269 + z288) - MF*z225 - MF*(z271 + z289)*sm.cos(Q5) + MF*(z273 + z290)*sm.sin(Q5)) + z226*(-MF*z226 + MF*(z232 + z238 + z267 + z287)*sm.sin(Q3)*sm.cos(Q4) - MF*(z240 + z241 + z269 + z288)*sm.cos(Q3)*sm.cos(Q4)) + z232*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239) - MR*(z232 + z238)) + z237*z468*sm.sin(Q5)*sm.cos(Q4)/z76 - z237*z474*sm.cos(Q4)*sm.cos(Q5)/z76 + z238*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239) - MR*(z232 + z238)) + z239*(-MB*z245*sm.cos(Q3) - MB*z246*sm.sin(Q3)*sm.sin(Q4) - MB*(z232 + z238 + z239)) + z240*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242) - MR*(z240 + z241)) + z241*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242) - MR*(z240 + z241)) + z242*(-MB*z245*sm.sin(Q3) + MB*z246*sm.sin(Q4)*sm.cos(Q3) - MB*(z240 + z241 + z242)) + z245*(-MB*z245 - MB*(z232 + z238 + z239)*sm.cos(Q3) - MB*(z240 + z241 + z242)*sm.sin(Q3)) + z246*(-MB*z246 - MB*(z232 + z238 + z239)*sm.sin(Q3)*sm.sin(Q4) + MB*(z240 + z241 + z242)*sm.sin(Q4)*sm.cos(Q3)) + z275*(-MH*z14*(z232 + z238 + z267 + z268) - MH*z15*(z240 + z241 + z269 + z270) - MH*z275 - MH*(z271 + z272)*sm.cos(Q5) + MH*(z273 + z274)*sm.sin(Q5)) + z276*(-MH*z276 + MH*(z232 + z238 + z267 + z268)*sm.sin(Q3)*sm.cos(Q4) - MH*(z240 + z241 + z269 + z270)*sm.cos(Q3)*sm.cos(Q4)) + z471*(-z237*sm.sin(Q4)/z76 - z244/z76) + z478*(-z237*sm.sin(Q4)/z76 - z244/z76) + z482*(-z237*z3/z76 - z244*sm.sin(Q7)/z76) + z485*(-z237*z4/z76 - z244*sm.cos(Q7)/z76) + z488*(-z237*sm.cos(Q4)*sm.cos(Q5)/z76 - 1) + z491*(-z237*z430/z76 - z244*sm.sin(Q7)*sm.cos(Q8)/z76 + sm.sin(Q8)) + z494*(-z237*z4/z76 - z244*sm.cos(Q7)/z76 - z462/z76) + z497*(-z237*z432/z76 - z244*sm.sin(Q7)*sm.sin(Q8)/z76 - sm.cos(Q8)) + (z271 + z272)*(-MH*z275*sm.cos(Q5) - MH*(z271 + z272) - MH*(z232 + z238 + z267 + z268)*sm.cos(Q3) - MH*(z240 + z241 + z269 + z270)*sm.sin(Q3)) + (z271 + z289)*(-MF*z225*sm.cos(Q5) - MF*(z271 + z289) - MF*(z232 + z238 + z267 + z287)*sm.cos(Q3) - MF*(z240 + z241 + z269 + z288)*sm.sin(Q3)) + (z273 + z274)*(MH*z275*sm.sin(Q5) - MH*(z273 + z274) - MH*(z232 + z238 + z267 + z268)*sm.sin(Q3)*sm.sin(Q4) + MH*(z240 + z241 + z269 + z270)*sm.sin(Q4)*sm.cos(Q3)) + (z273 + z290)*(MF*z225*sm.sin(Q5) - MF*(z273 + z290) - MF*(z232 + z238 + z267 + z287)*sm.sin(Q3)*sm.sin(Q4) + MF*(z240 + z241 + z269 + z288)*sm.sin(Q4)*sm.cos(Q3)) + (z232 + z238 + z267 + z268)*(-MH*z14*z275 + MH*z276*sm.sin(Q3)*sm.cos(Q4) - MH*(z271 + z272)*sm.cos(Q3) - MH*(z273 + z274)*sm.sin(Q3)*sm.sin(Q4) - MH*(z232 + z238 + z267 + z268)) + (z232 + z238 + z267 + z287)*(-MF*z14*z225 + MF*z226*sm.sin(Q3)*sm.cos(Q4) - MF*(z271 + z289)*sm.cos(Q3) - MF*(z273 + z290)*sm.sin(Q3)*sm.sin(Q4) - MF*(z232 + z238 + z267 + z287)) + (z240 + z241 + z269 + z270)*(-MH*z15*z275 - MH*z276*sm.cos(Q3)*sm.cos(Q4) - MH*(z271 + z272)*sm.sin(Q3) + MH*(z273 + z274)*sm.sin(Q4)*sm.cos(Q3) - MH*(z240 + z241 + z269 + z270)) + (z240 + z241 + z269 + z288)*(-MF*z15*z225 - MF*z226*sm.cos(Q3)*sm.cos(Q4) - MF*(z271 + z289)*sm.sin(Q3) + MF*(z273 + z290)*sm.sin(Q4)*sm.cos(Q3) - MF*(z240 + z241 + z269 + z288))),
    (Q3p, U3),
    (z18, -Q4p*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5)*sm.cos(Q4))),
    (z300, -Q3p*(Q4p*RR*sm.cos(Q4) + z18)*sm.cos(Q3)),
    (z301, -Q3p*(Q4p*RR*sm.cos(Q4) + z18)*sm.sin(Q3)),
    (Q5p, U5),
    (z16, Q5p*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5))),
    (z17, -Q5p*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q5) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.cos(Q5))),
    (z304, -Q3p*(z16*sm.sin(Q3) - z17*sm.sin(Q4)*sm.cos(Q3))),
    (z305, Q3p*(z16*sm.cos(Q3) + z17*sm.sin(Q3)*sm.sin(Q4))),
    (z314, (IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*(Q3p*sm.cos(Q4)*sm.cos(Q5) + Q4p*sm.sin(Q5)) + (-Q3p*sm.sin(Q5)*sm.cos(Q4) + Q4p*sm.cos(Q5))*(IBXX*sm.cos(LAM)**2 - 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.sin(LAM)**2)),
    (z316, (IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*(-Q3p*sm.sin(Q5)*sm.cos(Q4) + Q4p*sm.cos(Q5)) + (Q3p*sm.cos(Q4)*sm.cos(Q5) + Q4p*sm.sin(Q5))*(IBXX*sm.sin(LAM)**2 + 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.cos(LAM)**2)),
    (z317, Q5p*(-z314*sm.sin(Q5) + z316*sm.cos(Q5))),
    (z318, -Q5p*(z314*sm.cos(Q5) + z316*sm.sin(Q5))),
    (z315, IBYY*(Q3p*sm.sin(Q4) + Q5p)),
    (z319, -Q4p*(-z314*sm.sin(Q5)*sm.cos(Q4) + z315*sm.sin(Q4) + z316*sm.cos(Q4)*sm.cos(Q5))),
    (z320, Q4p*(z314*sm.sin(Q4)*sm.sin(Q5) + z315*sm.cos(Q4) - z316*sm.sin(Q4)*sm.cos(Q5))),
    (z321, -Q3p*(z10*z316 + z15*z314 + z315*sm.cos(Q3)*sm.cos(Q4))),
    (z322, Q3p*(z14*z314 - z315*sm.sin(Q3)*sm.cos(Q4) + z316*z7)),
    (z323, -Q3p*Q4p*RR*sm.cos(Q3)*sm.cos(Q4)),
    (z324, -Q3p*Q4p*RR*sm.sin(Q3)*sm.cos(Q4)),
    (z347, IRXX*(Q3p*z335 + Q4p*z333)),
    (z349, IRXX*(Q3p*z338 + Q4p*z336)),
    (z350, Q6p*(-z347*sm.sin(Q6) + z349*sm.cos(Q6))),
    (z351, -Q6p*(z347*sm.cos(Q6) + z349*sm.sin(Q6))),
    (z343, -sm.sin(Q5)*sm.cos(Q6) - sm.sin(Q6)*sm.cos(Q5)),
    (z352, Q5p*(z333*z349 + z343*z347)),
    (z353, -Q5p*(z333*z347 + z336*z349)),
    (z348, IRYY*(Q3p*sm.sin(Q4) + Q5p + Q6p)),
    (z354, -Q4p*(z335*z347 + z338*z349 + z348*sm.sin(Q4))),
    (z334, sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q6) + sm.sin(Q4)*sm.sin(Q6)*sm.cos(Q5)),
    (z337, sm.sin(Q4)*sm.sin(Q5)*sm.sin(Q6) - sm.sin(Q4)*sm.cos(Q5)*sm.cos(Q6)),
    (z355, Q4p*(z334*z347 + z337*z349 + z348*sm.cos(Q4))),
    (z340, -z10*sm.sin(Q6) + z15*sm.cos(Q6)),
    (z342, z10*sm.cos(Q6) + z15*sm.sin(Q6)),
    (z356, -Q3p*(z340*z347 + z342*z349 + z348*sm.cos(Q3)*sm.cos(Q4))),
    (z339, z14*sm.cos(Q6) - z7*sm.sin(Q6)),
    (z341, z14*sm.sin(Q6) + z7*sm.cos(Q6)),
    (z357, Q3p*(z339*z347 + z341*z349 - z348*sm.sin(Q3)*sm.cos(Q4))),
    (z23, -Q5p*((CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))),
    (z41, -Q5p*(((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q5) + (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q5)*sm.cos(Q7))),
    (z370, -Q4p*(z23 + z41)*sm.cos(Q4)),
    (z371, -Q4p*(z23 + z41)*sm.sin(Q4)),
    (z38, -Q7p*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q7)),
    (z39, Q7p*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q7)),
    (z376, -Q4p*(-z38*sm.sin(Q5)*sm.cos(Q4) + z39*sm.sin(Q4))),
    (z377, Q4p*(z38*sm.sin(Q4)*sm.sin(Q5) + z39*sm.cos(Q4))),
    (z392, (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*(Q3p*sm.cos(Q4)*sm.cos(Q5) + Q4p*sm.sin(Q5) + Q7p) + (IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2)*(Q3p*z3 + Q4p*sm.cos(Q5)*sm.cos(Q7) + Q5p*sm.sin(Q7))),
    (z393, IHYY*(Q3p*z4 - Q4p*sm.sin(Q7)*sm.cos(Q5) + Q5p*sm.cos(Q7))),
    (z395, -Q7p*(z392*sm.sin(Q7) + z393*sm.cos(Q7))),
    (z396, Q7p*(z392*sm.cos(Q7) - z393*sm.sin(Q7))),
    (z394, (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*(Q3p*z3 + Q4p*sm.cos(Q5)*sm.cos(Q7) + Q5p*sm.sin(Q7)) + (IHXX*sm.sin(LAM)**2 + 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.cos(LAM)**2)*(Q3p*sm.cos(Q4)*sm.cos(Q5) + Q4p*sm.sin(Q5) + Q7p)),
    (z397, Q5p*(-z392*sm.sin(Q5)*sm.cos(Q7) + z393*sm.sin(Q5)*sm.sin(Q7) + z394*sm.cos(Q5))),
    (z398, -Q5p*(z392*sm.cos(Q5)*sm.cos(Q7) - z393*sm.sin(Q7)*sm.cos(Q5) + z394*sm.sin(Q5))),
    (z399, -Q4p*(z3*z392 + z393*z4 + z394*sm.cos(Q4)*sm.cos(Q5))),
    (z400, Q4p*(z1*z392 + z2*z393 - z394*sm.sin(Q4)*sm.cos(Q5))),
    (z401, -Q3p*(z10*z394 + z392*z8 + z393*z9)),
    (z402, Q3p*(z392*z5 + z393*z6 + z394*z7)),
    (z31, Q5p*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7)),
    (z407, -Q4p*(z23 + z31)*sm.cos(Q4)),
    (z408, -Q4p*(z23 + z31)*sm.sin(Q4)),
    (z411, -Q4p*(-z28*sm.sin(Q5)*sm.cos(Q4) + z29*sm.sin(Q4))),
    (z412, Q4p*(z28*sm.sin(Q4)*sm.sin(Q5) + z29*sm.cos(Q4))),
    (Q8p, U8),
    (z440, IFXX*(Q3p*z430 + Q4p*z425 + Q5p*sm.sin(Q7)*sm.cos(Q8) - Q7p*sm.sin(Q8))),
    (z442, IFXX*(Q3p*z432 + Q4p*z427 + Q5p*sm.sin(Q7)*sm.sin(Q8) + Q7p*sm.cos(Q8))),
    (z443, Q8p*(-z440*sm.sin(Q8) + z442*sm.cos(Q8))),
    (z444, -Q8p*(z440*sm.cos(Q8) + z442*sm.sin(Q8))),
    (z441, IFYY*(Q3p*z4 - Q4p*sm.sin(Q7)*sm.cos(Q5) + Q5p*sm.cos(Q7) + Q8p)),
    (z445, -Q7p*(z440*sm.sin(Q7)*sm.cos(Q8) + z441*sm.cos(Q7) + z442*sm.sin(Q7)*sm.sin(Q8))),
    (z446, Q7p*(z440*sm.cos(Q7)*sm.cos(Q8) - z441*sm.sin(Q7) + z442*sm.sin(Q8)*sm.cos(Q7))),
    (z426, -sm.sin(Q5)*sm.cos(Q7)*sm.cos(Q8) - sm.sin(Q8)*sm.cos(Q5)),
    (z428, -sm.sin(Q5)*sm.sin(Q8)*sm.cos(Q7) + sm.cos(Q5)*sm.cos(Q8)),
    (z447, Q5p*(z426*z440 + z428*z442 + z441*sm.sin(Q5)*sm.sin(Q7))),
    (z448, -Q5p*(z425*z440 + z427*z442 - z441*sm.sin(Q7)*sm.cos(Q5))),
    (z449, -Q4p*(z4*z441 + z430*z440 + z432*z442)),
    (z429, z1*sm.cos(Q8) + sm.sin(Q4)*sm.sin(Q8)*sm.cos(Q5)),
    (z431, z1*sm.sin(Q8) - sm.sin(Q4)*sm.cos(Q5)*sm.cos(Q8)),
    (z450, Q4p*(z2*z441 + z429*z440 + z431*z442)),
    (z434, -z10*sm.sin(Q8) + z8*sm.cos(Q8)),
    (z436, z10*sm.cos(Q8) + z8*sm.sin(Q8)),
    (z451, -Q3p*(z434*z440 + z436*z442 + z441*z9)),
    (z433, z5*sm.cos(Q8) - z7*sm.sin(Q8)),
    (z435, z5*sm.sin(Q8) + z7*sm.cos(Q8)),
    (z452, Q3p*(z433*z440 + z435*z442 + z441*z6)),
    (z507, Q7p**2*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q7)),
    (z508, Q7p**2*(CT - RF*sm.tan(LAM))*sm.sin(Q7)*sm.cos(LAM)),
    (z509, -Q4p**2*((CT - RR*sm.tan(LAM) + W)*sm.sin(Q4)*sm.sin(Q5)*sm.cos(LAM) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5)/sm.cos(LAM)) - Q4p*Q5p*(-(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q4)*sm.cos(Q5) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q4)/sm.cos(LAM))),
    (z105, Q4p*(sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4)) - Q5p*sm.cos(Q4)*sm.cos(Q5)*sm.cos(Q7) + Q7p*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))),
    (z510, Q4p*z105*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z511, -Q4p**2*RR*sm.sin(Q4) + z509 + z510),
    (z515, Q4p**2*((CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q4) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5)/sm.cos(LAM)) + Q4p*Q5p*((CT - RR*sm.tan(LAM) + W)*sm.sin(Q4)*sm.cos(LAM)*sm.cos(Q5) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q4)*sm.sin(Q5)/sm.cos(LAM))),
    (z111, Q4p*(-sm.sin(Q4)*sm.sin(Q7) + sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7)) + Q5p*sm.sin(Q4)*sm.cos(Q5)*sm.cos(Q7) + Q7p*(-sm.sin(Q4)*sm.sin(Q5)*sm.sin(Q7) + sm.cos(Q4)*sm.cos(Q7))),
    (z516, -Q4p*z111*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z517, Q4p**2*RR*sm.cos(Q4) + z515 + z516),
    (z106, Q4p*(-sm.sin(Q4)*sm.sin(Q5)*sm.sin(Q7) + sm.cos(Q4)*sm.cos(Q7)) + Q5p*sm.sin(Q7)*sm.cos(Q4)*sm.cos(Q5) + Q7p*(-sm.sin(Q4)*sm.sin(Q7) + sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7))),
    (z107, -z106*z4/(1 - z4**2)**(sm.Rational(1, 2))),
    (z108, Q3p*(-sm.sin(Q3)*sm.sin(Q5) + sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5)) + Q4p*sm.sin(Q3)*sm.cos(Q4)*sm.cos(Q5) + Q5p*(-sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5))),
    (z109, Q3p*(-sm.sin(Q3)*sm.cos(Q5) - sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3)) - Q4p*sm.sin(Q3)*sm.sin(Q5)*sm.cos(Q4) + Q5p*(-sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) - sm.sin(Q5)*sm.cos(Q3))),
    (z110, z108*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) + z109*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)),
    (z112, Q3p*(-z1*sm.cos(Q3) - sm.sin(Q3)*sm.cos(Q5)*sm.cos(Q7)) - Q5p*sm.sin(Q5)*sm.cos(Q3)*sm.cos(Q7) - Q7p*sm.sin(Q7)*sm.cos(Q3)*sm.cos(Q5) - z111*sm.sin(Q3)),
    (z113, -z112*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z114, -Q4p*RF*sm.sin(Q4)*sm.cos(Q5)/z11 - Q5p*RF*sm.sin(Q5)*sm.cos(Q4)/z11 - RF*z107*sm.cos(Q4)*sm.cos(Q5)/z11**2),
    (z115, Q4p*(-sm.sin(Q4)*sm.cos(Q7) - sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4)) - Q5p*sm.sin(Q4)*sm.sin(Q7)*sm.cos(Q5) + Q7p*(-sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) - sm.sin(Q7)*sm.cos(Q4))),
    (z116, Q3p*(-z2*sm.cos(Q3) + sm.sin(Q3)*sm.sin(Q7)*sm.cos(Q5)) + Q5p*sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q3) - Q7p*sm.cos(Q3)*sm.cos(Q5)*sm.cos(Q7) - z115*sm.sin(Q3)),
    (z117, -RF*z106*z6/z11 + RF*z107*z4*z6/z11**2 - RF*z116*z4/z11),
    (z118, -Q3p*RR*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q4)*sm.cos(Q3) + Q4p*(RF*z3*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q4)*sm.cos(Q5)/z11 - RR*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q3)*sm.cos(Q4)) + Q5p*RF*z3*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q5)*sm.cos(Q4)/z11 + RF*z107*z3*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.cos(Q4)*sm.cos(Q5)/z11**2 + z105*(-RF*sm.cos(Q4)*sm.cos(Q5)/z11 + z66)*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69) + z110*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66) + z113*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66) + z114*z3*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69) + z117*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)),
    (z119, Q3p*(-z2*sm.sin(Q3) - sm.sin(Q7)*sm.cos(Q3)*sm.cos(Q5)) + Q5p*sm.sin(Q3)*sm.sin(Q5)*sm.sin(Q7) - Q7p*sm.sin(Q3)*sm.cos(Q5)*sm.cos(Q7) + z115*sm.cos(Q3)),
    (z120, Q5p*(-(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))),
    (z121, Q5p*((CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))),
    (z122, Q3p*(sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3)) - Q4p*sm.cos(Q3)*sm.cos(Q4)*sm.cos(Q5) + Q5p*(sm.sin(Q3)*sm.cos(Q5) + sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3))),
    (z123, Q3p*(-sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5)) + Q4p*sm.sin(Q5)*sm.cos(Q3)*sm.cos(Q4) + Q5p*(-sm.sin(Q3)*sm.sin(Q5) + sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5))),
    (z124, -z122*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) - z123*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)),
    (z125, Q5p*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7) - Q7p*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.sin(Q7)*sm.cos(LAM)),
    (z126, -Q5p*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7) - Q7p*(CT - RF*sm.tan(LAM))*sm.sin(Q7)*sm.cos(LAM)*sm.cos(Q5)),
    (z127, Q3p*(-z1*sm.sin(Q3) + sm.cos(Q3)*sm.cos(Q5)*sm.cos(Q7)) - Q5p*sm.sin(Q3)*sm.sin(Q5)*sm.cos(Q7) - Q7p*sm.sin(Q3)*sm.sin(Q7)*sm.cos(Q5) + z111*sm.cos(Q3)),
    (z128, z127*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z129, -Q4p*RF*sm.sin(Q4)/z11 - Q5p*RF*z4*sm.sin(Q7)*sm.cos(Q5)/z11 - Q7p*RF*z4*sm.sin(Q5)*sm.cos(Q7)/z11 - RF*z106*sm.sin(Q5)*sm.sin(Q7)/z11 + z107*(RF*z4*sm.sin(Q5)*sm.sin(Q7)/z11**2 - RF*sm.cos(Q4)/z11**2)),
    (z130, Q5p*RF*z4*sm.sin(Q5)*sm.sin(Q7)/z11 - Q7p*RF*z4*sm.cos(Q5)*sm.cos(Q7)/z11 - RF*z106*sm.sin(Q7)*sm.cos(Q5)/z11 + RF*z107*z4*sm.sin(Q7)*sm.cos(Q5)/z11**2),
    (z131, Q3p*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*(z58*sm.cos(Q3) + z59*sm.sin(Q3)*sm.sin(Q4) + z62*sm.cos(Q3) + z63*sm.sin(Q3)*sm.sin(Q4) + z67*sm.cos(Q3) + z68*sm.sin(Q3)*sm.sin(Q4)) + Q4p*(RF*z3*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4)*sm.cos(Q5)/z11 + (RF*z10*z3/z11 - z66*z8)*(-z59*sm.sin(Q4) - z63*sm.sin(Q4) - z68*sm.sin(Q4)) + (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*(-z59*sm.cos(Q3)*sm.cos(Q4) - z63*sm.cos(Q3)*sm.cos(Q4) - z68*sm.cos(Q3)*sm.cos(Q4))) + Q5p*RF*z3*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)/z11 + RF*z122*z3*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))/z11 + z105*(RF*z10*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))/z11 + (-RF*sm.cos(Q4)*sm.cos(Q5)/z11 + z66)*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))) + z107*(-RF*z10*z3*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))/z11**2 + RF*z3*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.cos(Q4)*sm.cos(Q5)/z11**2) + z114*(z3*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3)) - z8*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))) + z120*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q3) + z121*((RF*z10*z3/z11 - z66*z8)*sm.cos(Q4) - (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q4)*sm.cos(Q3)) + z125*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q3) + z126*((RF*z10*z3/z11 - z66*z8)*sm.cos(Q4) - (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q4)*sm.cos(Q3)) - z127*z66*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + z129*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q3) + z130*((RF*z10*z3/z11 - z66*z8)*sm.cos(Q4) - (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q4)*sm.cos(Q3))),
    (z132, -Q3p*RR*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.sin(Q4)*sm.cos(Q3) + Q4p*(-RR*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.sin(Q3)*sm.cos(Q4) + (-z59*sm.sin(Q4) - z63*sm.sin(Q4) - z68*sm.sin(Q4))*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)) + z110*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + z113*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + z117*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + z121*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.cos(Q4) + z126*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.cos(Q4) + z130*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.cos(Q4)),
    (z133, Q3p*(RR*z70*sm.sin(Q3)*sm.sin(Q4) + z71*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))) + Q4p*(-RR*z70*sm.cos(Q3)*sm.cos(Q4) + z71*(-z59*sm.sin(Q3)*sm.cos(Q4) - z63*sm.sin(Q3)*sm.cos(Q4) - z68*sm.sin(Q3)*sm.cos(Q4))) - RF*z105*z7*z72/z11 + RF*z106*z70*z9/z11 - RF*z108*z3*z72/z11 + RF*z119*z4*z70/z11 + z107*(RF*z3*z7*z72/z11**2 - RF*z4*z70*z9/z11**2) + z112*z66*z72 + z114*z5*z72 + z118*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) - z120*z71*sm.cos(Q3) - z121*z71*sm.sin(Q3)*sm.sin(Q4) + z124*z70 - z125*z71*sm.cos(Q3) - z126*z71*sm.sin(Q3)*sm.sin(Q4) + z128*z70 - z129*z71*sm.cos(Q3) - z130*z71*sm.sin(Q3)*sm.sin(Q4) + z131*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64) + z132*(-RF*z3*z7/z11 + z5*z66)),
    (z134, Q4p*RF*z3*sm.sin(Q4)*sm.cos(Q5)/z11 + Q5p*RF*z3*sm.sin(Q5)*sm.cos(Q4)/z11 + RF*z107*z3*sm.cos(Q4)*sm.cos(Q5)/z11**2 + z105*(-RF*sm.cos(Q4)*sm.cos(Q5)/z11 + z66) + z114*z3),
    (z135, -Q3p*RR*z74*sm.sin(Q3)*sm.sin(Q4) + Q4p*RR*z74*sm.cos(Q3)*sm.cos(Q4) - RF*z106*z74*z9/z11 + RF*z107*z4*z74*z9/z11**2 - RF*z119*z4*z74/z11 - z124*z74 - z128*z74 + z134*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64)),
    (z136, Q3p*(-RR*z71*sm.sin(Q3) + RR*z75*sm.cos(Q3)) + RR*z118*sm.cos(Q3) + RR*z135*sm.sin(Q3) + z133),
    (z512, -Q4p*Q7p*RF*sm.cos(Q4)/z11 - Q7p**2*RF*z4*sm.sin(Q7)/z11 + Q7p*RF*z106*sm.cos(Q7)/z11 + z107*(-Q7p*RF*z4*sm.cos(Q7)/z11**2 + Q7p*RF*sm.sin(Q4)/z11**2)),
    (z513, Q4p*Q7p*RF*sm.sin(Q4)*sm.sin(Q5)/z11 - Q5p*Q7p*RF*sm.cos(Q4)*sm.cos(Q5)/z11 + Q7p**2*RF*z4*sm.cos(Q7)/z11 + Q7p*RF*z106*sm.sin(Q7)/z11 + z107*(-Q7p*RF*z4*sm.sin(Q7)/z11**2 + Q7p*RF*sm.sin(Q5)*sm.cos(Q4)/z11**2)),
    (z514, 2*Q4p*RF*z106*z4/z11 + z107*(-Q4p*RF*z4**2/z11**2 + Q4p*RF/z11**2)),
    (z518, -Q4p*RF*z106*z2/z11 + Q4p*RF*z107*z2*z4/z11**2 - Q4p*RF*z115*z4/z11),
    (z519, Q3p*((z29 + z51)*sm.sin(Q3)*sm.cos(Q4) + (z36 + z54)*sm.sin(Q3))*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66) + Q4p*(RF*z3*(-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))*sm.sin(Q4)*sm.cos(Q5)/z11 + (z29 + z51)*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.sin(Q4)*sm.cos(Q3) + (-(z28 + z50)*sm.sin(Q4)*sm.sin(Q5) - (z29 + z51)*sm.cos(Q4))*(RF*z10*z3/z11 - z66*z8)) + Q5p*(RF*z3*(-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)/z11 + (z28 + z50)*(RF*z10*z3/z11 - z66*z8)*sm.cos(Q4)*sm.cos(Q5)) + RF*z122*z3*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))/z11 + z105*(RF*z10*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))/z11 + (-RF*sm.cos(Q4)*sm.cos(Q5)/z11 + z66)*(-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))) + z107*(-RF*z10*z3*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))/z11**2 + RF*z3*(-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))*sm.cos(Q4)*sm.cos(Q5)/z11**2) + z114*(z3*(-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3)) - z8*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))) + z123*(-z28 - z50)*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66) - z127*z66*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4)) + z507*(-z15*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66) + (RF*z10*z3/z11 - z66*z8)*sm.sin(Q5)*sm.cos(Q4)) + z508*(-(RF*z10*z3/z11 - z66*z8)*sm.sin(Q4) - (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.cos(Q3)*sm.cos(Q4)) - z511*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.cos(Q3) + z512*(-z15*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66) + (RF*z10*z3/z11 - z66*z8)*sm.sin(Q5)*sm.cos(Q4)) + z513*(-(RF*z10*z3/z11 - z66*z8)*sm.sin(Q4) - (-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.cos(Q3)*sm.cos(Q4)) - z514*(-RF*z3*sm.cos(Q4)*sm.cos(Q5)/z11 + z3*z66)*sm.cos(Q3) + z517*(-RF*z10*z3/z11 + z66*z8) + z518*(-RF*z10*z3/z11 + z66*z8)),
    (z520, Q3p*RR*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q4)*sm.cos(Q3) + Q4p*(RR*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q3)*sm.cos(Q4) + (-(z28 + z50)*sm.sin(Q4)*sm.sin(Q5) - (z29 + z51)*sm.cos(Q4))*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)) + Q5p*(z28 + z50)*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.cos(Q4)*sm.cos(Q5) + z110*(z37 + z55 - (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) + (z29 + z51)*sm.sin(Q4)) + z113*(z37 + z55 - (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) + (z29 + z51)*sm.sin(Q4)) + z117*(z37 + z55 - (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) + (z29 + z51)*sm.sin(Q4)) + z507*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.sin(Q5)*sm.cos(Q4) - z508*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.sin(Q4) + z512*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.sin(Q5)*sm.cos(Q4) - z513*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)*sm.sin(Q4) + z517*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69) + z518*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)),
    (z521, Q3p*(-RR*z77*sm.sin(Q3)*sm.sin(Q4) + z71*((z29 + z51)*sm.cos(Q3)*sm.cos(Q4) + (z36 + z54)*sm.cos(Q3))) + Q4p*(RR*z77*sm.cos(Q3)*sm.cos(Q4) - z71*(z29 + z51)*sm.sin(Q3)*sm.sin(Q4)) - RF*z105*z7*z78/z11 - RF*z106*z77*z9/z11 - RF*z108*z3*z78/z11 - RF*z119*z4*z77/z11 + z107*(RF*z3*z7*z78/z11**2 + RF*z4*z77*z9/z11**2) + z109*z71*(-z28 - z50) + z112*z66*z78 + z114*z5*z78 + z118*(-z14*(z28 + z50) + (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) + (z36 + z54)*sm.sin(Q3)) - z124*z77 - z128*z77 - z14*z507*z71 - z14*z512*z71 + z508*z71*sm.sin(Q3)*sm.cos(Q4) + z511*z71*sm.sin(Q3) + z513*z71*sm.sin(Q3)*sm.cos(Q4) + z514*z71*sm.sin(Q3) + z519*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64) + z520*(-RF*z3*z7/z11 + z5*z66)),
    (z522, Q5p*z75*(-Q6p*RR*z10*sm.cos(Q5) + Q6p*RR*z15*sm.sin(Q5)) - Q6p*RR*z122*z75*sm.sin(Q5) - Q6p*RR*z123*z75*sm.cos(Q5) + z135*(-Q6p*RR*z10*sm.sin(Q5) - Q6p*RR*z15*sm.cos(Q5)) - z521),
    (z523, Q3p*(RR*z75*(-Q6p*RR*z14*sm.cos(Q5) - Q6p*RR*z7*sm.sin(Q5))*sm.cos(Q3) + RR*z80*sm.sin(Q3)) + Q5p*(RR*z75*sm.sin(Q3) + z73)*(Q6p*RR*z14*sm.sin(Q5) - Q6p*RR*z7*sm.cos(Q5)) - Q6p*RR*z108*(RR*z75*sm.sin(Q3) + z73)*sm.sin(Q5) - Q6p*RR*z109*(RR*z75*sm.sin(Q3) + z73)*sm.cos(Q5) + RR*z135*(-Q6p*RR*z14*sm.cos(Q5) - Q6p*RR*z7*sm.sin(Q5))*sm.sin(Q3) - RR*z522*sm.cos(Q3) + z133*(-Q6p*RR*z14*sm.cos(Q5) - Q6p*RR*z7*sm.sin(Q5))),
    (z524, -z136*z81/z76**2 + z523/z76),
    (z525, Q3p*RR*z79*sm.cos(Q3) + Q5p*z73*(-Q6p*RR*z10*sm.cos(Q5) + Q6p*RR*z15*sm.sin(Q5)) - Q6p*RR*z122*z73*sm.sin(Q5) - Q6p*RR*z123*z73*sm.cos(Q5) + RR*z521*sm.sin(Q3) + z133*(-Q6p*RR*z10*sm.sin(Q5) - Q6p*RR*z15*sm.cos(Q5))),
    (z526, Q5p*z71*(Q6p*RR*z10*sm.cos(Q5) - Q6p*RR*z15*sm.sin(Q5)) + Q6p*RR*z122*z71*sm.sin(Q5) + Q6p*RR*z123*z71*sm.cos(Q5) + z118*(Q6p*RR*z10*sm.sin(Q5) + Q6p*RR*z15*sm.cos(Q5))),
    (z527, Q3p*(RR*z71*(Q6p*RR*z14*sm.cos(Q5) + Q6p*RR*z7*sm.sin(Q5))*sm.cos(Q3) + RR*z83*sm.sin(Q3)) + Q5p*RR*z71*(-Q6p*RR*z14*sm.sin(Q5) + Q6p*RR*z7*sm.cos(Q5))*sm.sin(Q3) + Q6p*RR**2*z108*z71*sm.sin(Q3)*sm.sin(Q5) + Q6p*RR**2*z109*z71*sm.sin(Q3)*sm.cos(Q5) + RR*z118*(Q6p*RR*z14*sm.cos(Q5) + Q6p*RR*z7*sm.sin(Q5))*sm.sin(Q3) - RR*z526*sm.cos(Q3) + z525),
    (z528, -z136*z84/z76**2 + z527/z76),
    (z166, Q3p*RR*z74*sm.cos(Q3) + RR*z134*sm.sin(Q3) - z131),
    (z161, Q4p*(-z59*sm.sin(Q4) - z63*sm.sin(Q4) - z68*sm.sin(Q4)) + z121*sm.cos(Q4) + z126*sm.cos(Q4) + z130*sm.cos(Q4)),
    (z162, Q3p*z74*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3)) + Q4p*z74*(-z59*sm.sin(Q3)*sm.cos(Q4) - z63*sm.sin(Q3)*sm.cos(Q4) - z68*sm.sin(Q3)*sm.cos(Q4)) - RF*z105*z7*z87/z11 + RF*z107*z3*z7*z87/z11**2 - RF*z108*z3*z87/z11 + z112*z66*z87 + z114*z5*z87 - z120*z74*sm.cos(Q3) - z121*z74*sm.sin(Q3)*sm.sin(Q4) - z125*z74*sm.cos(Q3) - z126*z74*sm.sin(Q3)*sm.sin(Q4) - z129*z74*sm.cos(Q3) - z130*z74*sm.sin(Q3)*sm.sin(Q4) + z134*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z161*(-RF*z3*z7/z11 + z5*z66)),
    (z529, Q3p*(((z29 + z51)*sm.sin(Q3)*sm.cos(Q4) + (z36 + z54)*sm.sin(Q3))*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4))) + Q4p*((z29 + z51)*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.sin(Q4)*sm.cos(Q3) + (-(z28 + z50)*sm.sin(Q4)*sm.sin(Q5) - (z29 + z51)*sm.cos(Q4))*(-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3)) + (-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))*(-z59*sm.sin(Q4) - z63*sm.sin(Q4) - z68*sm.sin(Q4)) + (z59*sm.cos(Q3)*sm.cos(Q4) + z63*sm.cos(Q3)*sm.cos(Q4) + z68*sm.cos(Q3)*sm.cos(Q4))*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))) + Q5p*(z28 + z50)*(-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.cos(Q4)*sm.cos(Q5) - z120*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q3) + z121*((-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))*sm.cos(Q4) + (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q4)*sm.cos(Q3)) + z123*(-z28 - z50)*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) - z125*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q3) + z126*((-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))*sm.cos(Q4) + (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q4)*sm.cos(Q3)) - z129*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q3) + z130*((-z15*(z28 + z50) - (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))*sm.cos(Q4) + (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q4)*sm.cos(Q3)) + z507*(-z15*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)) + z508*(-(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)*sm.cos(Q4) - (-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4)) - z511*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3) + z512*(-z15*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)) + z513*(-(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)*sm.cos(Q4) - (-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4)) - z514*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3) + z517*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3)) + z518*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))),
    (z530, Q3p*(z70*((z29 + z51)*sm.cos(Q3)*sm.cos(Q4) + (z36 + z54)*sm.cos(Q3)) + z77*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))) + Q4p*(-z70*(z29 + z51)*sm.sin(Q3)*sm.sin(Q4) + z77*(-z59*sm.sin(Q3)*sm.cos(Q4) - z63*sm.sin(Q3)*sm.cos(Q4) - z68*sm.sin(Q3)*sm.cos(Q4))) - RF*z105*z7*z85/z11 + RF*z107*z3*z7*z85/z11**2 - RF*z108*z3*z85/z11 + z109*z70*(-z28 - z50) + z112*z66*z85 + z114*z5*z85 - z120*z77*sm.cos(Q3) - z121*z77*sm.sin(Q3)*sm.sin(Q4) - z125*z77*sm.cos(Q3) - z126*z77*sm.sin(Q3)*sm.sin(Q4) - z129*z77*sm.cos(Q3) - z130*z77*sm.sin(Q3)*sm.sin(Q4) + z131*(-z14*(z28 + z50) + (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) + (z36 + z54)*sm.sin(Q3)) - z14*z507*z70 - z14*z512*z70 + z508*z70*sm.sin(Q3)*sm.cos(Q4) + z511*z70*sm.sin(Q3) + z513*z70*sm.sin(Q3)*sm.cos(Q4) + z514*z70*sm.sin(Q3) + z519*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z529*(-RF*z3*z7/z11 + z5*z66)),
    (z531, Q4p*(-(z28 + z50)*sm.sin(Q4)*sm.sin(Q5) - (z29 + z51)*sm.cos(Q4)) + Q5p*(z28 + z50)*sm.cos(Q4)*sm.cos(Q5) + z507*sm.sin(Q5)*sm.cos(Q4) - z508*sm.sin(Q4) + z512*sm.sin(Q5)*sm.cos(Q4) - z513*sm.sin(Q4) - z517 - z518),
    (z532, Q3p*z74*(-(z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3)) + Q4p*z74*(z29 + z51)*sm.sin(Q3)*sm.sin(Q4) - RF*z105*z7*z89/z11 + RF*z107*z3*z7*z89/z11**2 - RF*z108*z3*z89/z11 + z109*z74*(z28 + z50) + z112*z66*z89 + z114*z5*z89 + z134*(z14*(z28 + z50) - (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) - (z36 + z54)*sm.sin(Q3)) + z14*z507*z74 + z14*z512*z74 - z508*z74*sm.sin(Q3)*sm.cos(Q4) - z511*z74*sm.sin(Q3) - z513*z74*sm.sin(Q3)*sm.cos(Q4) - z514*z74*sm.sin(Q3) + z531*(-RF*z3*z7/z11 + z5*z66)),
    (z533, Q3p*RR*z90*sm.cos(Q3) + Q5p*z88*(Q6p*RR*z10*sm.cos(Q5) - Q6p*RR*z15*sm.sin(Q5)) + Q6p*RR*z122*z88*sm.sin(Q5) + Q6p*RR*z123*z88*sm.cos(Q5) + RR*z532*sm.sin(Q3) + z162*(Q6p*RR*z10*sm.sin(Q5) + Q6p*RR*z15*sm.cos(Q5)) + z530),
    (z534, Q5p*z74*(-Q6p*RR*z10*sm.cos(Q5) + Q6p*RR*z15*sm.sin(Q5)) - Q6p*RR*z122*z74*sm.sin(Q5) - Q6p*RR*z123*z74*sm.cos(Q5) + z134*(-Q6p*RR*z10*sm.sin(Q5) - Q6p*RR*z15*sm.cos(Q5)) - z519),
    (z535, Q3p*RR*z93*sm.sin(Q3) + Q5p*z92*(Q6p*RR*z14*sm.sin(Q5) - Q6p*RR*z7*sm.cos(Q5)) - Q6p*RR*z108*z92*sm.sin(Q5) - Q6p*RR*z109*z92*sm.cos(Q5) - RR*z534*sm.cos(Q3) + z166*(-Q6p*RR*z14*sm.cos(Q5) - Q6p*RR*z7*sm.sin(Q5)) + z533),
    (z536, -z136*z94/z76**2 + z535/z76),
    (z537, Q3p**2*RR*sm.sin(Q3)*sm.sin(Q4) - Q3p*Q4p*RR*sm.cos(Q3)*sm.cos(Q4) - RR*z536*sm.sin(Q4)*sm.cos(Q3)),
    (z538, -Q3p*z122*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)) - Q3p*z123*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)) + z536*(-z10*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)) - z15*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)))),
    (z539, -Q3p**2*RR*sm.sin(Q4)*sm.cos(Q3) - Q3p*Q4p*RR*sm.sin(Q3)*sm.cos(Q4) - RR*z536*sm.sin(Q3)*sm.sin(Q4)),
    (z540, Q3p*z108*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)) + Q3p*z109*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)) + z536*(z14*(XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM)) + z7*(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM)))),
    (z541, -Q3p*RR*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q4)*sm.cos(Q3) + Q4p*(-RR*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q3)*sm.cos(Q4) + (-(z28 + z50)*sm.sin(Q4)*sm.sin(Q5) - (z29 + z51)*sm.cos(Q4))*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)) + Q5p*(z28 + z50)*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.cos(Q4)*sm.cos(Q5) + z110*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4)) + z113*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4)) + z117*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4)) + z507*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q5)*sm.cos(Q4) - z508*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q4) + z512*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q5)*sm.cos(Q4) - z513*(-RR*sm.sin(Q3)*sm.sin(Q4) + z61 + z65 + z69)*sm.sin(Q4) + z517*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69) + z518*(RR*sm.sin(Q3)*sm.sin(Q4) - z61 - z65 - z69)),
    (z542, Q3p*(RR*z77*sm.sin(Q3)*sm.sin(Q4) + z71*(-(z29 + z51)*sm.cos(Q3)*sm.cos(Q4) - (z36 + z54)*sm.cos(Q3))) + Q4p*(-RR*z77*sm.cos(Q3)*sm.cos(Q4) + z71*(z29 + z51)*sm.sin(Q3)*sm.sin(Q4)) - RF*z105*z7*z95/z11 + RF*z106*z77*z9/z11 - RF*z108*z3*z95/z11 + RF*z119*z4*z77/z11 + z107*(RF*z3*z7*z95/z11**2 - RF*z4*z77*z9/z11**2) + z109*z71*(z28 + z50) + z112*z66*z95 + z114*z5*z95 + z118*(z14*(z28 + z50) - (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) - (z36 + z54)*sm.sin(Q3)) + z124*z77 + z128*z77 + z14*z507*z71 + z14*z512*z71 - z508*z71*sm.sin(Q3)*sm.cos(Q4) - z511*z71*sm.sin(Q3) - z513*z71*sm.sin(Q3)*sm.cos(Q4) - z514*z71*sm.sin(Q3) + z519*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64) + z541*(-RF*z3*z7/z11 + z5*z66)),
    (z543, Q5p*z75*(-Q6p*RR*z10*sm.cos(Q5) + Q6p*RR*z15*sm.sin(Q5)) - Q6p*RR*z122*z75*sm.sin(Q5) - Q6p*RR*z123*z75*sm.cos(Q5) + z135*(-Q6p*RR*z10*sm.sin(Q5) - Q6p*RR*z15*sm.cos(Q5)) + z542),
    (z544, -Q5p*z71*(-Q6p*RR*z14*sm.sin(Q5) + Q6p*RR*z7*sm.cos(Q5)) - Q6p*RR*z108*z71*sm.sin(Q5) - Q6p*RR*z109*z71*sm.cos(Q5) + z118*(-Q6p*RR*z14*sm.cos(Q5) - Q6p*RR*z7*sm.sin(Q5)) + z543),
    (z545, -z136*z98/z76**2 + z544/z76),
    (z546, Q5p**2*(-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.cos(Q5)) + z545*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5))),
    (z547, -Q5p**2*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5)) + z545*(-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.cos(Q5))),
    (z548, -Q4p**2*(-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q4)*sm.sin(Q5)) - Q4p*Q5p*(-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q4) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.cos(Q4)*sm.cos(Q5))),
    (z549, -Q4p**2*RR*sm.sin(Q4) - Q4p*z17*sm.cos(Q4) + z548),
    (z550, Q4p**2*(-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5)*sm.cos(Q4)) + Q4p*Q5p*((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q4)*sm.sin(Q5) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q4)*sm.cos(Q5))),
    (z551, Q4p**2*RR*sm.cos(Q4) - Q4p*z17*sm.sin(Q4) + z550),
    (z309, -Q3p*Q5p*sm.sin(Q3)*sm.cos(Q4)),
    (z308, -Q3p*Q5p*sm.cos(Q3)*sm.cos(Q4)),
    (z310, -Q3p*Q4p*sm.sin(Q3) + z308),
    (z552, (IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*(Q4p*Q5p*sm.sin(Q4)**2*sm.cos(Q5) + Q4p*Q5p*sm.cos(Q4)**2*sm.cos(Q5) + z10*(Q3p*Q4p*sm.cos(Q3) + z309) + z310*z7 + z536*sm.cos(Q4)*sm.cos(Q5)) + (IBXX*sm.cos(LAM)**2 - 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.sin(LAM)**2)*(-Q4p*Q5p*sm.sin(Q4)**2*sm.sin(Q5) - Q4p*Q5p*sm.sin(Q5)*sm.cos(Q4)**2 + z14*z310 + z15*(Q3p*Q4p*sm.cos(Q3) + z309) - z536*sm.sin(Q5)*sm.cos(Q4))),
    (z553, IBYY*(-z310*sm.sin(Q3)*sm.cos(Q4) + z536*sm.sin(Q4) + z545 + (Q3p*Q4p*sm.cos(Q3) + z309)*sm.cos(Q3)*sm.cos(Q4))),
    (z554, (IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM))*(-Q4p*Q5p*sm.sin(Q4)**2*sm.sin(Q5) - Q4p*Q5p*sm.sin(Q5)*sm.cos(Q4)**2 + z14*z310 + z15*(Q3p*Q4p*sm.cos(Q3) + z309) - z536*sm.sin(Q5)*sm.cos(Q4)) + (IBXX*sm.sin(LAM)**2 + 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.cos(LAM)**2)*(Q4p*Q5p*sm.sin(Q4)**2*sm.cos(Q5) + Q4p*Q5p*sm.cos(Q4)**2*sm.cos(Q5) + z10*(Q3p*Q4p*sm.cos(Q3) + z309) + z310*z7 + z536*sm.cos(Q4)*sm.cos(Q5))),
    (z555, -Q4p**2*RR*sm.sin(Q4)),
    (z329, -Q4p*Q5p*sm.sin(Q4) - Q4p*Q6p*sm.sin(Q4)),
    (z330, Q4p*Q5p*sm.cos(Q4) + Q4p*Q6p*sm.cos(Q4)),
    (z327, -Q3p*Q6p*sm.cos(Q3)*sm.cos(Q4)),
    (z331, -Q3p*Q4p*sm.sin(Q3) + z308 + z327),
    (z328, -Q3p*Q6p*sm.sin(Q3)*sm.cos(Q4)),
    (z332, Q3p*Q4p*sm.cos(Q3) + z309 + z328),
    (z556, IRXX*(z329*z334 + z330*z335 + z331*z339 + z332*z340 + z335*z536)),
    (z557, IRYY*(z329*sm.cos(Q4) + z330*sm.sin(Q4) - z331*sm.sin(Q3)*sm.cos(Q4) + z332*sm.cos(Q3)*sm.cos(Q4) + z536*sm.sin(Q4) + z545)),
    (z558, IRXX*(z329*z337 + z330*z338 + z331*z341 + z332*z342 + z338*z536)),
    (z559, Q4p**2*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q4)*sm.cos(Q5) + Q4p*Q5p*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q5)*sm.cos(Q4) - Q4p*z105*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))),
    (z560, -Q4p**2*RR*sm.sin(Q4) + z509 + z559),
    (z561, -Q4p**2*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q4)*sm.cos(Q5) + Q4p*Q5p*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q4)*sm.sin(Q5) + Q4p*z111*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))),
    (z562, Q4p**2*RR*sm.cos(Q4) + z515 + z561),
    (z563, -Q7p**2*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q7)),
    (z564, -Q7p**2*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q7)),
    (z42, -Q4p*(z3*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) + ((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q4)*sm.cos(Q5))),
    (z46, Q4p*RR*sm.cos(Q4) + z24 + z42),
    (z22, Q5p*(-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))),
    (z40, Q5p*(((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q7))),
    (z372, -Q3p*((z22 + z40)*sm.sin(Q3) - (z23 + z41)*sm.sin(Q4)*sm.cos(Q3))),
    (z378, -Q3p*(z15*z38 + z39*sm.cos(Q3)*sm.cos(Q4))),
    (z565, -Q3p*z122*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) - Q3p*z123*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + z536*(-z10*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) - z15*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM))),
    (z566, -Q3p*z122*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)) - Q3p*z127*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) + z536*(-z10*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)) - z8*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)))),
    (z567, -Q3p*z46*sm.cos(Q3) + z372 + z378 + z524 + z537 + z565 + z566),
    (z373, Q3p*((z22 + z40)*sm.cos(Q3) + (z23 + z41)*sm.sin(Q3)*sm.sin(Q4))),
    (z379, Q3p*(z14*z38 - z39*sm.sin(Q3)*sm.cos(Q4))),
    (z568, Q3p*z108*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) + Q3p*z109*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + z536*(z14*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + z7*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM))),
    (z569, Q3p*z108*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)) + Q3p*z112*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) + z536*(z5*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)) + z7*((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM)))),
    (z570, -Q3p*z46*sm.sin(Q3) + z373 + z379 + z528 + z539 + z568 + z569),
    (z571, Q5p**2*(-(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM)) + z545*(-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))),
    (z572, Q5p**2*(-((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q5)*sm.cos(Q7)) + Q5p*Q7p*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q5)*sm.sin(Q7) + z545*(((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q7))),
    (z573, -Q5p*z38*sm.sin(Q5) + z571 + z572),
    (z574, -Q5p**2*(-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM)) + z545*(-(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))),
    (z575, -Q5p**2*(((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q7)) + Q5p*Q7p*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q7)*sm.cos(Q5) + z545*(-((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q5)*sm.cos(Q7))),
    (z576, -Q5p*z38*sm.cos(Q5) + z574 + z575),
    (z385, -Q4p*Q7p*sm.sin(Q4)*sm.cos(Q5)),
    (z384, -Q4p*Q7p*sm.cos(Q4)*sm.cos(Q5)),
    (z386, -Q4p*Q5p*sm.sin(Q4) + z384),
    (z387, -Q3p*Q4p*sm.sin(Q3) - Q3p*Q7p*z10 + z308),
    (z388, Q3p*Q4p*sm.cos(Q3) + Q3p*Q7p*z7 + z309),
    (z577, (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*(z10*z388 - z386*sm.sin(Q4)*sm.cos(Q5) + z387*z7 + z536*sm.cos(Q4)*sm.cos(Q5) + (Q4p*Q5p*sm.cos(Q4) + z385)*sm.cos(Q4)*sm.cos(Q5)) + (IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2)*(Q5p*Q7p*sm.sin(Q5)**2*sm.cos(Q7) + Q5p*Q7p*sm.cos(Q5)**2*sm.cos(Q7) + z1*z386 + z3*z536 + z3*(Q4p*Q5p*sm.cos(Q4) + z385) + z387*z5 + z388*z8 + z545*sm.sin(Q7))),
    (z578, IHYY*(-Q5p*Q7p*sm.sin(Q5)**2*sm.sin(Q7) - Q5p*Q7p*sm.sin(Q7)*sm.cos(Q5)**2 + z2*z386 + z387*z6 + z388*z9 + z4*z536 + z4*(Q4p*Q5p*sm.cos(Q4) + z385) + z545*sm.cos(Q7))),
    (z579, (IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM))*(Q5p*Q7p*sm.sin(Q5)**2*sm.cos(Q7) + Q5p*Q7p*sm.cos(Q5)**2*sm.cos(Q7) + z1*z386 + z3*z536 + z3*(Q4p*Q5p*sm.cos(Q4) + z385) + z387*z5 + z388*z8 + z545*sm.sin(Q7)) + (IHXX*sm.sin(LAM)**2 + 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.cos(LAM)**2)*(z10*z388 - z386*sm.sin(Q4)*sm.cos(Q5) + z387*z7 + z536*sm.cos(Q4)*sm.cos(Q5) + (Q4p*Q5p*sm.cos(Q4) + z385)*sm.cos(Q4)*sm.cos(Q5))),
    (z30, Q5p*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7)),
    (z409, -Q3p*((z22 + z30)*sm.sin(Q3) - (z23 + z31)*sm.sin(Q4)*sm.cos(Q3))),
    (z413, -Q3p*(z15*z28 + z29*sm.cos(Q3)*sm.cos(Q4))),
    (z580, Q3p*z127*(CT - RF*sm.tan(LAM))*sm.cos(LAM) + z536*z8*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z581, -Q3p*z36*sm.cos(Q3) + z409 + z413 + z524 + z537 + z565 + z580),
    (z410, Q3p*((z22 + z30)*sm.cos(Q3) + (z23 + z31)*sm.sin(Q3)*sm.sin(Q4))),
    (z414, Q3p*(z14*z28 - z29*sm.sin(Q3)*sm.cos(Q4))),
    (z582, -Q3p*z112*(CT - RF*sm.tan(LAM))*sm.cos(LAM) - z5*z536*(CT - RF*sm.tan(LAM))*sm.cos(LAM)),
    (z583, -Q3p*z36*sm.sin(Q3) + z410 + z414 + z528 + z539 + z568 + z582),
    (z584, Q5p**2*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7) - Q5p*Q7p*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.sin(Q7)*sm.cos(LAM) + z545*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7)),
    (z585, -Q5p*z28*sm.sin(Q5) + z571 + z584),
    (z586, -Q5p**2*(CT - RF*sm.tan(LAM))*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7) - Q5p*Q7p*(CT - RF*sm.tan(LAM))*sm.sin(Q7)*sm.cos(LAM)*sm.cos(Q5) + z545*(CT - RF*sm.tan(LAM))*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7)),
    (z587, -Q5p*z28*sm.cos(Q5) + z574 + z586),
    (z419, Q5p*Q7p*sm.cos(Q5) + Q5p*Q8p*sm.sin(Q5)*sm.sin(Q7)),
    (z420, -Q5p*Q7p*sm.sin(Q5) + Q5p*Q8p*sm.sin(Q7)*sm.cos(Q5)),
    (z421, -Q4p*Q5p*sm.sin(Q4) - Q4p*Q8p*z4 + z384),
    (z422, Q4p*Q5p*sm.cos(Q4) + Q4p*Q8p*z2 + z385),
    (z423, -Q3p*Q4p*sm.sin(Q3) - Q3p*Q7p*z10 - Q3p*Q8p*z9 + z308),
    (z424, Q3p*Q4p*sm.cos(Q3) + Q3p*Q7p*z7 + Q3p*Q8p*z6 + z309),
    (z588, IFXX*(-Q7p*Q8p*sm.sin(Q7)**2*sm.cos(Q8) - Q7p*Q8p*sm.cos(Q7)**2*sm.cos(Q8) + z419*z425 + z420*z426 + z421*z429 + z422*z430 + z423*z433 + z424*z434 + z430*z536 + z545*sm.sin(Q7)*sm.cos(Q8))),
    (z178, -Q3p*RR*z87*sm.sin(Q3)*sm.sin(Q4) + Q4p*RR*z87*sm.cos(Q3)*sm.cos(Q4) - RF*z106*z87*z9/z11 + RF*z107*z4*z87*z9/z11**2 - RF*z119*z4*z87/z11 - z124*z87 - z128*z87 + z161*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64)),
    (z589, Q3p*((-(z29 + z51)*sm.sin(Q3)*sm.cos(Q4) - (z36 + z54)*sm.sin(Q3))*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*(z58*sm.cos(Q3) + z59*sm.sin(Q3)*sm.sin(Q4) + z62*sm.cos(Q3) + z63*sm.sin(Q3)*sm.sin(Q4) + z67*sm.cos(Q3) + z68*sm.sin(Q3)*sm.sin(Q4))) + Q4p*(-(z29 + z51)*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.sin(Q4)*sm.cos(Q3) + (-(z28 + z50)*sm.sin(Q4)*sm.sin(Q5) - (z29 + z51)*sm.cos(Q4))*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3)) + (z15*(z28 + z50) + (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) + (z36 + z54)*sm.cos(Q3))*(-z59*sm.sin(Q4) - z63*sm.sin(Q4) - z68*sm.sin(Q4)) + (-z59*sm.cos(Q3)*sm.cos(Q4) - z63*sm.cos(Q3)*sm.cos(Q4) - z68*sm.cos(Q3)*sm.cos(Q4))*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))) + Q5p*(z28 + z50)*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.cos(Q4)*sm.cos(Q5) + z120*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q3) + z121*((z15*(z28 + z50) + (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) + (z36 + z54)*sm.cos(Q3))*sm.cos(Q4) - (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q4)*sm.cos(Q3)) + z123*(z28 + z50)*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + z125*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q3) + z126*((z15*(z28 + z50) + (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) + (z36 + z54)*sm.cos(Q3))*sm.cos(Q4) - (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q4)*sm.cos(Q3)) + z129*(-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q3) + z130*((z15*(z28 + z50) + (z29 + z51)*sm.cos(Q3)*sm.cos(Q4) + (z36 + z54)*sm.cos(Q3))*sm.cos(Q4) - (-z37 - z55 + (z28 + z50)*sm.sin(Q5)*sm.cos(Q4) - (z29 + z51)*sm.sin(Q4))*sm.sin(Q4)*sm.cos(Q3)) + z507*(z15*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)) + z508*((z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)*sm.cos(Q4) - (z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4)) + z511*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3) + z512*(z15*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4)) + (z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q5)*sm.cos(Q4)) + z513*((z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3)*sm.cos(Q4) - (z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))*sm.sin(Q4)) + z514*(z59*sm.cos(Q4) + z63*sm.cos(Q4) + z68*sm.cos(Q4))*sm.cos(Q3) + z517*(-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3)) + z518*(-z58*sm.sin(Q3) + z59*sm.sin(Q4)*sm.cos(Q3) - z62*sm.sin(Q3) + z63*sm.sin(Q4)*sm.cos(Q3) - z67*sm.sin(Q3) + z68*sm.sin(Q4)*sm.cos(Q3))),
    (z590, Q3p*(RR*z99*sm.sin(Q3)*sm.sin(Q4) + z72*((z29 + z51)*sm.cos(Q3)*sm.cos(Q4) + (z36 + z54)*sm.cos(Q3)) + z95*(z58*sm.sin(Q3) - z59*sm.sin(Q4)*sm.cos(Q3) + z62*sm.sin(Q3) - z63*sm.sin(Q4)*sm.cos(Q3) + z67*sm.sin(Q3) - z68*sm.sin(Q4)*sm.cos(Q3))) + Q4p*(-RR*z99*sm.cos(Q3)*sm.cos(Q4) - z72*(z29 + z51)*sm.sin(Q3)*sm.sin(Q4) + z95*(-z59*sm.sin(Q3)*sm.cos(Q4) - z63*sm.sin(Q3)*sm.cos(Q4) - z68*sm.sin(Q3)*sm.cos(Q4))) + RF*z106*z9*z99/z11 - RF*z107*z4*z9*z99/z11**2 + RF*z119*z4*z99/z11 + z109*z72*(-z28 - z50) - z120*z95*sm.cos(Q3) - z121*z95*sm.sin(Q3)*sm.sin(Q4) + z124*z99 - z125*z95*sm.cos(Q3) - z126*z95*sm.sin(Q3)*sm.sin(Q4) + z128*z99 - z129*z95*sm.cos(Q3) - z130*z95*sm.sin(Q3)*sm.sin(Q4) + z132*(-z14*(z28 + z50) + (z29 + z51)*sm.sin(Q3)*sm.cos(Q4) + (z36 + z54)*sm.sin(Q3)) - z14*z507*z72 - z14*z512*z72 + z508*z72*sm.sin(Q3)*sm.cos(Q4) + z511*z72*sm.sin(Q3) + z513*z72*sm.sin(Q3)*sm.cos(Q4) + z514*z72*sm.sin(Q3) + z541*(-z58*sm.cos(Q3) - z59*sm.sin(Q3)*sm.sin(Q4) - z62*sm.cos(Q3) - z63*sm.sin(Q3)*sm.sin(Q4) - z67*sm.cos(Q3) - z68*sm.sin(Q3)*sm.sin(Q4)) + z589*(RF*z4*z9/z11 - RR*sm.sin(Q4)*sm.cos(Q3) + z60 + z64)),
    (z591, -Q3p*RR*z89*sm.sin(Q3)*sm.sin(Q4) + Q4p*RR*z89*sm.cos(Q3)*sm.cos(Q4) - RF*z106*z89*z9/z11 + RF*z107*z4*z89*z9/z11**2 - RF*z119*z4*z89/z11 - z124*z89 - z128*z89 + z531*(-RF*z4*z9/z11 + RR*sm.sin(Q4)*sm.cos(Q3) - z60 - z64)),
    (z592, Q3p*RR*z101*sm.cos(Q3) + Q5p*z102*(Q6p*RR*z10*sm.cos(Q5) - Q6p*RR*z15*sm.sin(Q5)) + Q6p*RR*z102*z122*sm.sin(Q5) + Q6p*RR*z102*z123*sm.cos(Q5) + RR*z591*sm.sin(Q3) + z178*(Q6p*RR*z10*sm.sin(Q5) + Q6p*RR*z15*sm.cos(Q5)) + z590),
    (z593, -Q3p*RR*z95*sm.sin(Q3) - Q5p*z72*(Q6p*RR*z14*sm.sin(Q5) - Q6p*RR*z7*sm.cos(Q5)) + Q6p*RR*z108*z72*sm.sin(Q5) + Q6p*RR*z109*z72*sm.cos(Q5) + RR*z541*sm.cos(Q3) + z132*(Q6p*RR*z14*sm.cos(Q5) + Q6p*RR*z7*sm.sin(Q5)) + z592),
    (z594, -z104*z136/z76**2 + z593/z76),
    (z595, IFYY*(z2*z421 + z4*z422 + z4*z536 - z419*sm.sin(Q7)*sm.cos(Q5) + z420*sm.sin(Q5)*sm.sin(Q7) + z423*z6 + z424*z9 + z545*sm.cos(Q7) + z594)),
    (z596, IFXX*(-Q7p*Q8p*sm.sin(Q7)**2*sm.sin(Q8) - Q7p*Q8p*sm.sin(Q8)*sm.cos(Q7)**2 + z419*z427 + z420*z428 + z421*z431 + z422*z432 + z423*z435 + z424*z436 + z432*z536 + z545*sm.sin(Q7)*sm.sin(Q8))),
    (z597, -MB*z206*z546 - MB*z207*z547 - MB*z547*(RR*sm.sin(Q4) + z203)*sm.cos(Q4) + MB*z547*(RR*sm.cos(Q4) + z202)*sm.sin(Q4) - MB*z549*(RR*sm.cos(Q4) + z202) + MB*z549*(z191 + z197 + z198)*sm.sin(Q3) - MB*z549*(z199 + z200 + z201)*sm.cos(Q3) - MB*z551*(RR*sm.sin(Q4) + z203) - MB*(z191 + z197 + z198)*(z300 + z304 + z524 + z537 + z538) - MB*(z199 + z200 + z201)*(z301 + z305 + z528 + z539 + z540) - MF*z507*(z253 + z279)*sm.cos(Q5) + MF*z507*(z255 + z280)*sm.sin(Q5) - MF*z581*(z191 + z197 + z247 + z277) - MF*z583*(z199 + z200 + z249 + z278) - MF*z585*(z253 + z279) - MF*z587*(z255 + z280) - MF*z587*(RR*sm.sin(Q4) + z185 + z186)*sm.cos(Q4) + MF*z587*(RR*sm.cos(Q4) + z182 + z183)*sm.sin(Q4) - MF*(z407 + z411 + z511)*(RR*sm.cos(Q4) + z182 + z183) + MF*(z407 + z411 + z511)*(z191 + z197 + z247 + z277)*sm.sin(Q3) - MF*(z407 + z411 + z511)*(z199 + z200 + z249 + z278)*sm.cos(Q3) - MF*(z408 + z412 + z517)*(RR*sm.sin(Q4) + z185 + z186) - MH*z563*(z253 + z254)*sm.cos(Q5) + MH*z563*(z255 + z256)*sm.sin(Q5) - MH*z567*(z191 + z197 + z247 + z248) - MH*z570*(z199 + z200 + z249 + z250) - MH*z573*(z253 + z254) - MH*z576*(z255 + z256) - MH*z576*(RR*sm.sin(Q4) + z185 + z252)*sm.cos(Q4) + MH*z576*(RR*sm.cos(Q4) + z182 + z251)*sm.sin(Q4) - MH*(z370 + z376 + z560)*(RR*sm.cos(Q4) + z182 + z251) + MH*(z370 + z376 + z560)*(z191 + z197 + z247 + z248)*sm.sin(Q3) - MH*(z370 + z376 + z560)*(z199 + z200 + z249 + z250)*sm.cos(Q3) - MH*(z371 + z377 + z562)*(RR*sm.sin(Q4) + z185 + z252) - MR*Q4p**2*RR**2*sm.sin(Q4)*sm.cos(Q4) - MR*RR*z555*sm.cos(Q4) + MR*z555*(z191 + z197)*sm.sin(Q3) - MR*z555*(z199 + z200)*sm.cos(Q3) - MR*(z191 + z197)*(z323 + z524 + z537) - MR*(z199 + z200)*(z324 + z528 + z539) + RR*(MR*(z323 + z524 + z537)*sm.sin(Q3) - MR*(z324 + z528 + z539)*sm.cos(Q3))*sm.cos(Q4) - z196*z318*sm.cos(Q4)/z76 - z196*z320/z76 - z196*z353*sm.cos(Q4)/z76 - z196*z355/z76 - z196*z398*sm.cos(Q4)/z76 - z196*z400/z76 - z196*z448*sm.cos(Q4)/z76 - z196*z450/z76 + z196*(-z3*z443 - z444*sm.cos(Q4)*sm.cos(Q5))/z76 + z196*(z350*sm.sin(Q5)*sm.cos(Q4) - z351*sm.cos(Q4)*sm.cos(Q5))/z76 + z196*(z395*sm.sin(Q5)*sm.cos(Q4) - z396*sm.sin(Q4))/z76 + z196*(z445*sm.sin(Q5)*sm.cos(Q4) - z446*sm.sin(Q4))/z76 + z196*(-z3*z577 - z4*z578 - z579*sm.cos(Q4)*sm.cos(Q5))/z76 + z196*(-z335*z556 - z338*z558 - z557*sm.sin(Q4))/z76 + z196*(-z4*z595 - z430*z588 - z432*z596)/z76 + z196*(z552*sm.sin(Q5)*sm.cos(Q4) - z553*sm.sin(Q4) - z554*sm.cos(Q4)*sm.cos(Q5))/z76 - z205*z396/z76 - z205*z443*sm.sin(Q7)/z76 - z205*z446/z76 - z205*z553/z76 - z205*z557/z76 + z205*(-z319*sm.cos(Q4) - z320*sm.sin(Q4))/z76 + z205*(-z354*sm.cos(Q4) - z355*sm.sin(Q4))/z76 + z205*(-z399*sm.cos(Q4) - z400*sm.sin(Q4))/z76 + z205*(-z449*sm.cos(Q4) - z450*sm.sin(Q4))/z76 + z205*(-z577*sm.sin(Q7) - z578*sm.cos(Q7))/z76 + z205*(z321*sm.sin(Q3)*sm.cos(Q4) - z322*sm.cos(Q3)*sm.cos(Q4))/z76 + z205*(z356*sm.sin(Q3)*sm.cos(Q4) - z357*sm.cos(Q3)*sm.cos(Q4))/z76 + z205*(z401*sm.sin(Q3)*sm.cos(Q4) - z402*sm.cos(Q3)*sm.cos(Q4))/z76 + z205*(z451*sm.sin(Q3)*sm.cos(Q4) - z452*sm.cos(Q3)*sm.cos(Q4))/z76 + z205*(-z588*sm.sin(Q7)*sm.cos(Q8) - z595*sm.cos(Q7) - z596*sm.sin(Q7)*sm.sin(Q8))/z76 + z206*(-MB*(z300 + z304 + z524 + z537 + z538)*sm.cos(Q3) - MB*(z301 + z305 + z528 + z539 + z540)*sm.sin(Q3)) + z207*(MB*z549*sm.sin(Q4) - MB*z551*sm.cos(Q4)) + z207*(-MB*(z300 + z304 + z524 + z537 + z538)*sm.sin(Q3)*sm.sin(Q4) + MB*(z301 + z305 + z528 + z539 + z540)*sm.sin(Q4)*sm.cos(Q3)) - z317 - z321*sm.cos(Q3) - z322*sm.sin(Q3) - z333*z556 - z336*z558 - z350*sm.cos(Q5) - z351*sm.sin(Q5) - z352 - z356*sm.cos(Q3) - z357*sm.sin(Q3) - z395*sm.cos(Q5) - z397 - z401*sm.cos(Q3) - z402*sm.sin(Q3) - z425*z588 - z427*z596 - z443*sm.cos(Q5)*sm.cos(Q7) - z444*sm.sin(Q5) - z445*sm.cos(Q5) - z447 - z451*sm.cos(Q3) - z452*sm.sin(Q3) - z456*z595/z76 + z456*(-z2*z449 - z4*z450)/z76 + z456*(z445*sm.sin(Q7) - z446*sm.cos(Q7))/z76 + z456*(-z451*z6 - z452*z9)/z76 + z456*(z447*sm.sin(Q7)*sm.cos(Q5) - z448*sm.sin(Q5)*sm.sin(Q7))/z76 - z552*sm.cos(Q5) - z554*sm.sin(Q5) - z577*sm.cos(Q5)*sm.cos(Q7) + z578*sm.sin(Q7)*sm.cos(Q5) - z579*sm.sin(Q5) + z595*sm.sin(Q7)*sm.cos(Q5) + (z253 + z254)*(-MH*z567*sm.cos(Q3) - MH*z570*sm.sin(Q3)) + (z253 + z279)*(-MF*z581*sm.cos(Q3) - MF*z583*sm.sin(Q3)) + (z255 + z256)*(MH*(z370 + z376 + z560)*sm.sin(Q4) - MH*(z371 + z377 + z562)*sm.cos(Q4)) + (z255 + z256)*(-MH*z567*sm.sin(Q3)*sm.sin(Q4) + MH*z570*sm.sin(Q4)*sm.cos(Q3)) + (z255 + z280)*(MF*(z407 + z411 + z511)*sm.sin(Q4) - MF*(z408 + z412 + z517)*sm.cos(Q4)) + (z255 + z280)*(-MF*z581*sm.sin(Q3)*sm.sin(Q4) + MF*z583*sm.sin(Q4)*sm.cos(Q3)) + (RR*sm.cos(Q4) + z202)*(MB*(z300 + z304 + z524 + z537 + z538)*sm.sin(Q3) - MB*(z301 + z305 + z528 + z539 + z540)*sm.cos(Q3)) + (-MB*z546*sm.sin(Q3) + MB*z547*sm.sin(Q4)*sm.cos(Q3))*(z199 + z200 + z201) + (-MB*z546*sm.cos(Q3) - MB*z547*sm.sin(Q3)*sm.sin(Q4))*(z191 + z197 + z198) + (-MF*z14*z507 + MF*z508*sm.sin(Q3)*sm.cos(Q4))*(z191 + z197 + z247 + z277) + (-MF*z15*z507 - MF*z508*sm.cos(Q3)*sm.cos(Q4))*(z199 + z200 + z249 + z278) + (MF*z581*sm.sin(Q3) - MF*z583*sm.cos(Q3))*(RR*sm.cos(Q4) + z182 + z183) + (-MF*z585*sm.sin(Q3) + MF*z587*sm.sin(Q4)*sm.cos(Q3))*(z199 + z200 + z249 + z278) + (-MF*z585*sm.cos(Q3) - MF*z587*sm.sin(Q3)*sm.sin(Q4))*(z191 + z197 + z247 + z277) + (-MH*z14*z563 + MH*z564*sm.sin(Q3)*sm.cos(Q4))*(z191 + z197 + z247 + z248) + (-MH*z15*z563 - MH*z564*sm.cos(Q3)*sm.cos(Q4))*(z199 + z200 + z249 + z250) + (MH*z567*sm.sin(Q3) - MH*z570*sm.cos(Q3))*(RR*sm.cos(Q4) + z182 + z251) + (-MH*z573*sm.sin(Q3) + MH*z576*sm.sin(Q4)*sm.cos(Q3))*(z199 + z200 + z249 + z250) + (-MH*z573*sm.cos(Q3) - MH*z576*sm.sin(Q3)*sm.sin(Q4))*(z191 + z197 + z247 + z248) + (-MF*z507*sm.sin(Q4)*sm.sin(Q5) - MF*z508*sm.cos(Q4))*(RR*sm.cos(Q4) + z182 + z183) + (MF*z507*sm.sin(Q5)*sm.cos(Q4) - MF*z508*sm.sin(Q4))*(RR*sm.sin(Q4) + z185 + z186) + (-MH*z563*sm.sin(Q4)*sm.sin(Q5) - MH*z564*sm.cos(Q4))*(RR*sm.cos(Q4) + z182 + z251) + (MH*z563*sm.sin(Q5)*sm.cos(Q4) - MH*z564*sm.sin(Q4))*(RR*sm.sin(Q4) + z185 + z252)),
    (z598, MB*z215*z549*sm.sin(Q3) - MB*z215*(z300 + z304 + z524 + z537 + z538) - MB*z221*z549*sm.cos(Q3) - MB*z221*(z301 + z305 + z528 + z539 + z540) - MB*z223*z546 - MB*z224*z547 - MF*z282*z581 + MF*z282*(z407 + z411 + z511)*sm.sin(Q3) - MF*z284*z583 - MF*z284*(z407 + z411 + z511)*sm.cos(Q3) - MF*z507*(z263 + z285)*sm.cos(Q5) + MF*z507*(z265 + z286)*sm.sin(Q5) - MF*z585*(z263 + z285) - MF*z587*(z265 + z286) - MH*z259*z567 + MH*z259*(z370 + z376 + z560)*sm.sin(Q3) - MH*z262*z570 - MH*z262*(z370 + z376 + z560)*sm.cos(Q3) - MH*z563*(z263 + z264)*sm.cos(Q5) + MH*z563*(z265 + z266)*sm.sin(Q5) - MH*z573*(z263 + z264) - MH*z576*(z265 + z266) + MR*z555*(z209/z76 + z213)*sm.sin(Q3) - MR*z555*(z218/z76 + z219)*sm.cos(Q3) - MR*(z209/z76 + z213)*(z323 + z524 + z537) - MR*(z218/z76 + z219)*(z324 + z528 + z539) - z212*z318*sm.cos(Q4)/z76 - z212*z320/z76 - z212*z353*sm.cos(Q4)/z76 - z212*z355/z76 - z212*z398*sm.cos(Q4)/z76 - z212*z400/z76 - z212*z448*sm.cos(Q4)/z76 - z212*z450/z76 + z212*(-z3*z443 - z444*sm.cos(Q4)*sm.cos(Q5))/z76 + z212*(z350*sm.sin(Q5)*sm.cos(Q4) - z351*sm.cos(Q4)*sm.cos(Q5))/z76 + z212*(z395*sm.sin(Q5)*sm.cos(Q4) - z396*sm.sin(Q4))/z76 + z212*(z445*sm.sin(Q5)*sm.cos(Q4) - z446*sm.sin(Q4))/z76 + z212*(-z3*z577 - z4*z578 - z579*sm.cos(Q4)*sm.cos(Q5))/z76 + z212*(-z335*z556 - z338*z558 - z557*sm.sin(Q4))/z76 + z212*(-z4*z595 - z430*z588 - z432*z596)/z76 + z212*(z552*sm.sin(Q5)*sm.cos(Q4) - z553*sm.sin(Q4) - z554*sm.cos(Q4)*sm.cos(Q5))/z76 + z215*(-MB*z546*sm.cos(Q3) - MB*z547*sm.sin(Q3)*sm.sin(Q4)) + z221*(-MB*z546*sm.sin(Q3) + MB*z547*sm.sin(Q4)*sm.cos(Q3)) - z222*z396/z76 - z222*z443*sm.sin(Q7)/z76 - z222*z446/z76 - z222*z553/z76 - z222*z557/z76 + z222*(-z319*sm.cos(Q4) - z320*sm.sin(Q4))/z76 + z222*(-z354*sm.cos(Q4) - z355*sm.sin(Q4))/z76 + z222*(-z399*sm.cos(Q4) - z400*sm.sin(Q4))/z76 + z222*(-z449*sm.cos(Q4) - z450*sm.sin(Q4))/z76 + z222*(-z577*sm.sin(Q7) - z578*sm.cos(Q7))/z76 + z222*(z321*sm.sin(Q3)*sm.cos(Q4) - z322*sm.cos(Q3)*sm.cos(Q4))/z76 + z222*(z356*sm.sin(Q3)*sm.cos(Q4) - z357*sm.cos(Q3)*sm.cos(Q4))/z76 + z222*(z401*sm.sin(Q3)*sm.cos(Q4) - z402*sm.cos(Q3)*sm.cos(Q4))/z76 + z222*(z451*sm.sin(Q3)*sm.cos(Q4) - z452*sm.cos(Q3)*sm.cos(Q4))/z76 + z222*(-z588*sm.sin(Q7)*sm.cos(Q8) - z595*sm.cos(Q7) - z596*sm.sin(Q7)*sm.sin(Q8))/z76 + z223*(-MB*(z300 + z304 + z524 + z537 + z538)*sm.cos(Q3) - MB*(z301 + z305 + z528 + z539 + z540)*sm.sin(Q3)) + z224*(MB*z549*sm.sin(Q4) - MB*z551*sm.cos(Q4)) + z224*(-MB*(z300 + z304 + z524 + z537 + z538)*sm.sin(Q3)*sm.sin(Q4) + MB*(z301 + z305 + z528 + z539 + z540)*sm.sin(Q4)*sm.cos(Q3)) + z259*(-MH*z14*z563 + MH*z564*sm.sin(Q3)*sm.cos(Q4)) + z259*(-MH*z573*sm.cos(Q3) - MH*z576*sm.sin(Q3)*sm.sin(Q4)) + z262*(-MH*z15*z563 - MH*z564*sm.cos(Q3)*sm.cos(Q4)) + z262*(-MH*z573*sm.sin(Q3) + MH*z576*sm.sin(Q4)*sm.cos(Q3)) + z282*(-MF*z14*z507 + MF*z508*sm.sin(Q3)*sm.cos(Q4)) + z282*(-MF*z585*sm.cos(Q3) - MF*z587*sm.sin(Q3)*sm.sin(Q4)) + z284*(-MF*z15*z507 - MF*z508*sm.cos(Q3)*sm.cos(Q4)) + z284*(-MF*z585*sm.sin(Q3) + MF*z587*sm.sin(Q4)*sm.cos(Q3)) - z354*sm.cos(Q4) - z355*sm.sin(Q4) + z356*sm.sin(Q3)*sm.cos(Q4) - z357*sm.cos(Q3)*sm.cos(Q4) - z458*z595/z76 + z458*(-z2*z449 - z4*z450)/z76 + z458*(z445*sm.sin(Q7) - z446*sm.cos(Q7))/z76 + z458*(-z451*z6 - z452*z9)/z76 + z458*(z447*sm.sin(Q7)*sm.cos(Q5) - z448*sm.sin(Q5)*sm.sin(Q7))/z76 - z557 + (z263 + z264)*(-MH*z567*sm.cos(Q3) - MH*z570*sm.sin(Q3)) + (z263 + z285)*(-MF*z581*sm.cos(Q3) - MF*z583*sm.sin(Q3)) + (z265 + z266)*(MH*(z370 + z376 + z560)*sm.sin(Q4) - MH*(z371 + z377 + z562)*sm.cos(Q4)) + (z265 + z266)*(-MH*z567*sm.sin(Q3)*sm.sin(Q4) + MH*z570*sm.sin(Q4)*sm.cos(Q3)) + (z265 + z286)*(MF*(z407 + z411 + z511)*sm.sin(Q4) - MF*(z408 + z412 + z517)*sm.cos(Q4)) + (z265 + z286)*(-MF*z581*sm.sin(Q3)*sm.sin(Q4) + MF*z583*sm.sin(Q4)*sm.cos(Q3))),
    (z599, -MB*z245*z546 - MB*z246*z547 + MB*z549*(z232 + z238 + z239)*sm.sin(Q3) - MB*z549*(z240 + z241 + z242)*sm.cos(Q3) - MB*(z232 + z238 + z239)*(z300 + z304 + z524 + z537 + z538) - MB*(z240 + z241 + z242)*(z301 + z305 + z528 + z539 + z540) - MF*z225*z507 - MF*z226*z508 - MF*z507*(z271 + z289)*sm.cos(Q5) + MF*z507*(z273 + z290)*sm.sin(Q5) - MF*z581*(z232 + z238 + z267 + z287) - MF*z583*(z240 + z241 + z269 + z288) - MF*z585*(z271 + z289) - MF*z587*(z273 + z290) + MF*(z407 + z411 + z511)*(z232 + z238 + z267 + z287)*sm.sin(Q3) - MF*(z407 + z411 + z511)*(z240 + z241 + z269 + z288)*sm.cos(Q3) - MH*z275*z563 - MH*z276*z564 - MH*z563*(z271 + z272)*sm.cos(Q5) + MH*z563*(z273 + z274)*sm.sin(Q5) - MH*z567*(z232 + z238 + z267 + z268) - MH*z570*(z240 + z241 + z269 + z270) - MH*z573*(z271 + z272) - MH*z576*(z273 + z274) + MH*(z370 + z376 + z560)*(z232 + z238 + z267 + z268)*sm.sin(Q3) - MH*(z370 + z376 + z560)*(z240 + z241 + z269 + z270)*sm.cos(Q3) + MR*z555*(z232 + z238)*sm.sin(Q3) - MR*z555*(z240 + z241)*sm.cos(Q3) - MR*(z232 + z238)*(z323 + z524 + z537) - MR*(z240 + z241)*(z324 + z528 + z539) - z10*z402 - z10*z452 + z225*(-MF*z14*z581 - MF*z15*z583) + z225*(-MF*z585*sm.cos(Q5) + MF*z587*sm.sin(Q5)) + z225*(-MF*(z407 + z411 + z511)*sm.sin(Q4)*sm.sin(Q5) + MF*(z408 + z412 + z517)*sm.sin(Q5)*sm.cos(Q4)) + z226*(-MF*(z407 + z411 + z511)*sm.cos(Q4) - MF*(z408 + z412 + z517)*sm.sin(Q4)) + z226*(MF*z581*sm.sin(Q3)*sm.cos(Q4) - MF*z583*sm.cos(Q3)*sm.cos(Q4)) - z237*z318*sm.cos(Q4)/z76 - z237*z320/z76 - z237*z353*sm.cos(Q4)/z76 - z237*z355/z76 - z237*z398*sm.cos(Q4)/z76 - z237*z400/z76 - z237*z448*sm.cos(Q4)/z76 - z237*z450/z76 + z237*(-z3*z443 - z444*sm.cos(Q4)*sm.cos(Q5))/z76 + z237*(z350*sm.sin(Q5)*sm.cos(Q4) - z351*sm.cos(Q4)*sm.cos(Q5))/z76 + z237*(z395*sm.sin(Q5)*sm.cos(Q4) - z396*sm.sin(Q4))/z76 + z237*(z445*sm.sin(Q5)*sm.cos(Q4) - z446*sm.sin(Q4))/z76 + z237*(-z3*z577 - z4*z578 - z579*sm.cos(Q4)*sm.cos(Q5))/z76 + z237*(-z335*z556 - z338*z558 - z557*sm.sin(Q4))/z76 + z237*(-z4*z595 - z430*z588 - z432*z596)/z76 + z237*(z552*sm.sin(Q5)*sm.cos(Q4) - z553*sm.sin(Q4) - z554*sm.cos(Q4)*sm.cos(Q5))/z76 - z244*z396/z76 - z244*z443*sm.sin(Q7)/z76 - z244*z446/z76 - z244*z553/z76 - z244*z557/z76 + z244*(-z319*sm.cos(Q4) - z320*sm.sin(Q4))/z76 + z244*(-z354*sm.cos(Q4) - z355*sm.sin(Q4))/z76 + z244*(-z399*sm.cos(Q4) - z400*sm.sin(Q4))/z76 + z244*(-z449*sm.cos(Q4) - z450*sm.sin(Q4))/z76 + z244*(-z577*sm.sin(Q7) - z578*sm.cos(Q7))/z76 + z244*(z321*sm.sin(Q3)*sm.cos(Q4) - z322*sm.cos(Q3)*sm.cos(Q4))/z76 + z244*(z356*sm.sin(Q3)*sm.cos(Q4) - z357*sm.cos(Q3)*sm.cos(Q4))/z76 + z244*(z401*sm.sin(Q3)*sm.cos(Q4) - z402*sm.cos(Q3)*sm.cos(Q4))/z76 + z244*(z451*sm.sin(Q3)*sm.cos(Q4) - z452*sm.cos(Q3)*sm.cos(Q4))/z76 + z244*(-z588*sm.sin(Q7)*sm.cos(Q8) - z595*sm.cos(Q7) - z596*sm.sin(Q7)*sm.sin(Q8))/z76 + z245*(-MB*(z300 + z304 + z524 + z537 + z538)*sm.cos(Q3) - MB*(z301 + z305 + z528 + z539 + z540)*sm.sin(Q3)) + z246*(MB*z549*sm.sin(Q4) - MB*z551*sm.cos(Q4)) + z246*(-MB*(z300 + z304 + z524 + z537 + z538)*sm.sin(Q3)*sm.sin(Q4) + MB*(z301 + z305 + z528 + z539 + z540)*sm.sin(Q4)*sm.cos(Q3)) + z275*(-MH*z14*z567 - MH*z15*z570) + z275*(-MH*z573*sm.cos(Q5) + MH*z576*sm.sin(Q5)) + z275*(-MH*(z370 + z376 + z560)*sm.sin(Q4)*sm.sin(Q5) + MH*(z371 + z377 + z562)*sm.sin(Q5)*sm.cos(Q4)) + z276*(-MH*(z370 + z376 + z560)*sm.cos(Q4) - MH*(z371 + z377 + z562)*sm.sin(Q4)) + z276*(MH*z567*sm.sin(Q3)*sm.cos(Q4) - MH*z570*sm.cos(Q3)*sm.cos(Q4)) - z397*sm.sin(Q5) - z398*sm.cos(Q5) + z399*sm.sin(Q4)*sm.cos(Q5) - z400*sm.cos(Q4)*sm.cos(Q5) - z401*z7 - z444 - z447*sm.sin(Q5) - z448*sm.cos(Q5) + z449*sm.sin(Q4)*sm.cos(Q5) - z450*sm.cos(Q4)*sm.cos(Q5) - z451*z7 - z462*z595/z76 + z462*(-z2*z449 - z4*z450)/z76 + z462*(z445*sm.sin(Q7) - z446*sm.cos(Q7))/z76 + z462*(-z451*z6 - z452*z9)/z76 + z462*(z447*sm.sin(Q7)*sm.cos(Q5) - z448*sm.sin(Q5)*sm.sin(Q7))/z76 - z579 + z588*sm.sin(Q8) - z596*sm.cos(Q8) + (z271 + z272)*(-MH*z567*sm.cos(Q3) - MH*z570*sm.sin(Q3)) + (z271 + z289)*(-MF*z581*sm.cos(Q3) - MF*z583*sm.sin(Q3)) + (z273 + z274)*(MH*(z370 + z376 + z560)*sm.sin(Q4) - MH*(z371 + z377 + z562)*sm.cos(Q4)) + (z273 + z274)*(-MH*z567*sm.sin(Q3)*sm.sin(Q4) + MH*z570*sm.sin(Q4)*sm.cos(Q3)) + (z273 + z290)*(MF*(z407 + z411 + z511)*sm.sin(Q4) - MF*(z408 + z412 + z517)*sm.cos(Q4)) + (z273 + z290)*(-MF*z581*sm.sin(Q3)*sm.sin(Q4) + MF*z583*sm.sin(Q4)*sm.cos(Q3)) + (-MB*z546*sm.sin(Q3) + MB*z547*sm.sin(Q4)*sm.cos(Q3))*(z240 + z241 + z242) + (-MB*z546*sm.cos(Q3) - MB*z547*sm.sin(Q3)*sm.sin(Q4))*(z232 + z238 + z239) + (-MF*z14*z507 + MF*z508*sm.sin(Q3)*sm.cos(Q4))*(z232 + z238 + z267 + z287) + (-MF*z15*z507 - MF*z508*sm.cos(Q3)*sm.cos(Q4))*(z240 + z241 + z269 + z288) + (-MF*z585*sm.sin(Q3) + MF*z587*sm.sin(Q4)*sm.cos(Q3))*(z240 + z241 + z269 + z288) + (-MF*z585*sm.cos(Q3) - MF*z587*sm.sin(Q3)*sm.sin(Q4))*(z232 + z238 + z267 + z287) + (-MH*z14*z563 + MH*z564*sm.sin(Q3)*sm.cos(Q4))*(z232 + z238 + z267 + z268) + (-MH*z15*z563 - MH*z564*sm.cos(Q3)*sm.cos(Q4))*(z240 + z241 + z269 + z270) + (-MH*z573*sm.sin(Q3) + MH*z576*sm.sin(Q4)*sm.cos(Q3))*(z240 + z241 + z269 + z270) + (-MH*z573*sm.cos(Q3) - MH*z576*sm.sin(Q3)*sm.sin(Q4))*(z232 + z238 + z267 + z268)),
]
# those that need the solved rates (outputs only)
after_solving = [
]

states = [Q1, Q2, Q3, Q4, Q5, Q6, Q7, Q8, U4, U6, U7]
# d(state)/dt where it is given; None where it is solved (`unknowns`)
rates = [U1, U2, U3, U4, U5, U6, U7, U8, None, None, None]
unknowns = [U4p, U6p, U7p]
unknown_states = [8, 9, 10]
mass_matrix = sm.Matrix(3, 3, [-z498, -z499, -z500, -z501, -z502, -z503, -z504, -z505, -z506])
forcing = sm.Matrix(3, 1, [z291 + z597, z292 + z598, z293 + z599])

# as one system: full_mass * d(states)/dt = full_forcing
full_mass = sm.eye(len(states))
full_forcing = sm.Matrix([0 if r is None else r for r in rates])
for row, k in enumerate(unknown_states):
    full_mass[k, k] = 0
    for column, j in enumerate(unknown_states):
        full_mass[k, j] = mass_matrix[row, column]
    full_forcing[k] = forcing[row]
system = me.SymbolicSystem(states, full_forcing, mass_matrix=full_mass)

# values (SI units, radians) from the model's INPUT statements
constants = {CT: 0.08, G: 9.81, IBXX: 9.2, IBXZ: 2.4, IBYY: 11.0, IBZZ: 2.8, IFXX: 0.1405, IFYY: 0.28, IHXX: 0.05892, IHXZ: -0.00756, IHYY: 0.06, IHZZ: 0.00708, IRXX: 0.0603, IRYY: 0.12, LAM: 0.3141592653589793, MB: 85.0, MF: 3.0, MH: 4.0, MR: 2.0, RF: 0.35, RR: 0.3, W: 1.02, XB: 0.3, XH: 0.9, ZB: -0.9, ZH: -0.7}
initial_conditions = {Q1: 0.0, Q2: 0.0, Q3: 0.0, Q4: 0.0, Q5: 0.3141592653589793, Q6: 0.0, Q7: 0.0, Q8: 0.0, U4: 0.0, U6: -16.666666666666668, U7: 0.0}
# each a number or a function of time; 0 unless given
specified = {}
integration = {'TINITIAL': 0.0, 'TFINAL': 1.0, 'INTEGSTP': 0.1, 'ABSERR': 1e-08, 'RELERR': 1e-07, 'PRINTINT': 1}
# OUTPUT columns: (label, unit, expression in the unit)
outputs = [
    ('Q4', '', Q4),
    ('Q7', '', Q7),
]


def expanded(expr):
    """`expr` with every intermediate replaced by what it is (large for large models)."""
    for name, value in reversed(intermediates + after_solving):
        expr = expr.xreplace({name: value})
    return expr


def numeric_functions():
    """full_mass, full_forcing and the outputs as numpy functions of (t, state, constants,
    specified values[, unknowns]), each computing the intermediates in order."""
    plain = {f: sm.Dummy() for f in states + list(specified) + unknowns
             + [name for name, _ in intermediates + after_solving]}
    steps = [(plain[name], value.xreplace(plain)) for name, value in intermediates]
    late = [(plain[name], value.xreplace(plain)) for name, value in after_solving]
    arguments = [t, [plain[x] for x in states], list(constants),
                 [plain[s] for s in specified]]

    def function(expr, more=(), after=()):
        return sm.lambdify(arguments + list(more), expr.xreplace(plain), "numpy",
                           cse=lambda e: (steps + list(after), e))
    columns = sm.Matrix([e for _, _, e in outputs])
    return (function(full_mass), function(full_forcing),
            function(columns, [[plain[u] for u in unknowns]], late))


def integrate(tfinal=None):
    """The OUTPUT rows from TINITIAL to TFINAL (or `tfinal`) as Autolev's programs print
    them, as an array (a column per output)."""
    mass, force, columns = numeric_functions()
    p = [constants[c] for c in constants]
    x0 = np.array([initial_conditions[x] for x in states], dtype=float)
    t0, t1 = integration["TINITIAL"], tfinal if tfinal is not None else integration["TFINAL"]

    def values_of_specified(time):
        return [v(time) if callable(v) else v for v in specified.values()]

    def rates_of(time, x):
        s = values_of_specified(time)
        return np.linalg.solve(np.asarray(mass(time, x, p, s), dtype=float),
                               np.asarray(force(time, x, p, s), dtype=float).ravel())

    def row_at(time, x):
        rate = rates_of(time, x)
        return np.asarray(columns(time, x, p, values_of_specified(time),
                                  [rate[k] for k in unknown_states]), dtype=float).ravel()

    # Autolev's loop: a step of INTEGSTP while T + INTEGSTP/100 falls short of TFINAL,
    # a row every PRINTINT steps and after the last (which may pass TFINAL)
    h, every = integration["INTEGSTP"], integration["PRINTINT"]

    def done(time):
        ahead = time + 0.01 * h
        return ahead >= t1 if t1 >= t0 else ahead <= t1
    times, time, steps = [t0], t0, 0
    while not done(time):
        time, steps = time + h, steps + 1
        if steps % every == 0 or done(time):
            times.append(time)
    if len(times) == 1:
        return np.array([row_at(t0, x0)])
    solution = solve_ivp(rates_of, (t0, times[-1]), x0, method="DOP853", t_eval=times,
                         rtol=integration["RELERR"], atol=integration["ABSERR"])
    if not solution.success:
        raise RuntimeError(solution.message)
    return np.array([row_at(time, x) for time, x in zip(solution.t, solution.y.T)])


def main(argv):
    rows = integrate()
    text = ",".join(label for label, _, _ in outputs) + "\n" + "".join(
        ",".join(repr(float(v)) for v in row) + "\n" for row in rows)
    if argv:
        with open(argv[0], "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
