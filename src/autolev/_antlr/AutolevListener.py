# Generated from grammar/Autolev.g4 by ANTLR 4.13.2
from antlr4 import *
if "." in __name__:
    from .AutolevParser import AutolevParser
else:
    from AutolevParser import AutolevParser

# This class defines a complete listener for a parse tree produced by AutolevParser.
class AutolevListener(ParseTreeListener):

    # Enter a parse tree produced by AutolevParser#program.
    def enterProgram(self, ctx:AutolevParser.ProgramContext):
        pass

    # Exit a parse tree produced by AutolevParser#program.
    def exitProgram(self, ctx:AutolevParser.ProgramContext):
        pass


    # Enter a parse tree produced by AutolevParser#singleLine.
    def enterSingleLine(self, ctx:AutolevParser.SingleLineContext):
        pass

    # Exit a parse tree produced by AutolevParser#singleLine.
    def exitSingleLine(self, ctx:AutolevParser.SingleLineContext):
        pass


    # Enter a parse tree produced by AutolevParser#statementLine.
    def enterStatementLine(self, ctx:AutolevParser.StatementLineContext):
        pass

    # Exit a parse tree produced by AutolevParser#statementLine.
    def exitStatementLine(self, ctx:AutolevParser.StatementLineContext):
        pass


    # Enter a parse tree produced by AutolevParser#statement.
    def enterStatement(self, ctx:AutolevParser.StatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#statement.
    def exitStatement(self, ctx:AutolevParser.StatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#declaration.
    def enterDeclaration(self, ctx:AutolevParser.DeclarationContext):
        pass

    # Exit a parse tree produced by AutolevParser#declaration.
    def exitDeclaration(self, ctx:AutolevParser.DeclarationContext):
        pass


    # Enter a parse tree produced by AutolevParser#declKeyword.
    def enterDeclKeyword(self, ctx:AutolevParser.DeclKeywordContext):
        pass

    # Exit a parse tree produced by AutolevParser#declKeyword.
    def exitDeclKeyword(self, ctx:AutolevParser.DeclKeywordContext):
        pass


    # Enter a parse tree produced by AutolevParser#declarator.
    def enterDeclarator(self, ctx:AutolevParser.DeclaratorContext):
        pass

    # Exit a parse tree produced by AutolevParser#declarator.
    def exitDeclarator(self, ctx:AutolevParser.DeclaratorContext):
        pass


    # Enter a parse tree produced by AutolevParser#declRange.
    def enterDeclRange(self, ctx:AutolevParser.DeclRangeContext):
        pass

    # Exit a parse tree produced by AutolevParser#declRange.
    def exitDeclRange(self, ctx:AutolevParser.DeclRangeContext):
        pass


    # Enter a parse tree produced by AutolevParser#rangeBound.
    def enterRangeBound(self, ctx:AutolevParser.RangeBoundContext):
        pass

    # Exit a parse tree produced by AutolevParser#rangeBound.
    def exitRangeBound(self, ctx:AutolevParser.RangeBoundContext):
        pass


    # Enter a parse tree produced by AutolevParser#declSign.
    def enterDeclSign(self, ctx:AutolevParser.DeclSignContext):
        pass

    # Exit a parse tree produced by AutolevParser#declSign.
    def exitDeclSign(self, ctx:AutolevParser.DeclSignContext):
        pass


    # Enter a parse tree produced by AutolevParser#massStatement.
    def enterMassStatement(self, ctx:AutolevParser.MassStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#massStatement.
    def exitMassStatement(self, ctx:AutolevParser.MassStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#massItem.
    def enterMassItem(self, ctx:AutolevParser.MassItemContext):
        pass

    # Exit a parse tree produced by AutolevParser#massItem.
    def exitMassItem(self, ctx:AutolevParser.MassItemContext):
        pass


    # Enter a parse tree produced by AutolevParser#inertiaStatement.
    def enterInertiaStatement(self, ctx:AutolevParser.InertiaStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#inertiaStatement.
    def exitInertiaStatement(self, ctx:AutolevParser.InertiaStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#inertiaValue.
    def enterInertiaValue(self, ctx:AutolevParser.InertiaValueContext):
        pass

    # Exit a parse tree produced by AutolevParser#inertiaValue.
    def exitInertiaValue(self, ctx:AutolevParser.InertiaValueContext):
        pass


    # Enter a parse tree produced by AutolevParser#assignment.
    def enterAssignment(self, ctx:AutolevParser.AssignmentContext):
        pass

    # Exit a parse tree produced by AutolevParser#assignment.
    def exitAssignment(self, ctx:AutolevParser.AssignmentContext):
        pass


    # Enter a parse tree produced by AutolevParser#vectorTarget.
    def enterVectorTarget(self, ctx:AutolevParser.VectorTargetContext):
        pass

    # Exit a parse tree produced by AutolevParser#vectorTarget.
    def exitVectorTarget(self, ctx:AutolevParser.VectorTargetContext):
        pass


    # Enter a parse tree produced by AutolevParser#scalarTarget.
    def enterScalarTarget(self, ctx:AutolevParser.ScalarTargetContext):
        pass

    # Exit a parse tree produced by AutolevParser#scalarTarget.
    def exitScalarTarget(self, ctx:AutolevParser.ScalarTargetContext):
        pass


    # Enter a parse tree produced by AutolevParser#assignOp.
    def enterAssignOp(self, ctx:AutolevParser.AssignOpContext):
        pass

    # Exit a parse tree produced by AutolevParser#assignOp.
    def exitAssignOp(self, ctx:AutolevParser.AssignOpContext):
        pass


    # Enter a parse tree produced by AutolevParser#expressionStatement.
    def enterExpressionStatement(self, ctx:AutolevParser.ExpressionStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#expressionStatement.
    def exitExpressionStatement(self, ctx:AutolevParser.ExpressionStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#inputStatement.
    def enterInputStatement(self, ctx:AutolevParser.InputStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#inputStatement.
    def exitInputStatement(self, ctx:AutolevParser.InputStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#inputItem.
    def enterInputItem(self, ctx:AutolevParser.InputItemContext):
        pass

    # Exit a parse tree produced by AutolevParser#inputItem.
    def exitInputItem(self, ctx:AutolevParser.InputItemContext):
        pass


    # Enter a parse tree produced by AutolevParser#outputStatement.
    def enterOutputStatement(self, ctx:AutolevParser.OutputStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#outputStatement.
    def exitOutputStatement(self, ctx:AutolevParser.OutputStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#outputItem.
    def enterOutputItem(self, ctx:AutolevParser.OutputItemContext):
        pass

    # Exit a parse tree produced by AutolevParser#outputItem.
    def exitOutputItem(self, ctx:AutolevParser.OutputItemContext):
        pass


    # Enter a parse tree produced by AutolevParser#unitsStatement.
    def enterUnitsStatement(self, ctx:AutolevParser.UnitsStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#unitsStatement.
    def exitUnitsStatement(self, ctx:AutolevParser.UnitsStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#unitsItem.
    def enterUnitsItem(self, ctx:AutolevParser.UnitsItemContext):
        pass

    # Exit a parse tree produced by AutolevParser#unitsItem.
    def exitUnitsItem(self, ctx:AutolevParser.UnitsItemContext):
        pass


    # Enter a parse tree produced by AutolevParser#unitsTarget.
    def enterUnitsTarget(self, ctx:AutolevParser.UnitsTargetContext):
        pass

    # Exit a parse tree produced by AutolevParser#unitsTarget.
    def exitUnitsTarget(self, ctx:AutolevParser.UnitsTargetContext):
        pass


    # Enter a parse tree produced by AutolevParser#unitSystemStatement.
    def enterUnitSystemStatement(self, ctx:AutolevParser.UnitSystemStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#unitSystemStatement.
    def exitUnitSystemStatement(self, ctx:AutolevParser.UnitSystemStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#unit.
    def enterUnit(self, ctx:AutolevParser.UnitContext):
        pass

    # Exit a parse tree produced by AutolevParser#unit.
    def exitUnit(self, ctx:AutolevParser.UnitContext):
        pass


    # Enter a parse tree produced by AutolevParser#unitFactor.
    def enterUnitFactor(self, ctx:AutolevParser.UnitFactorContext):
        pass

    # Exit a parse tree produced by AutolevParser#unitFactor.
    def exitUnitFactor(self, ctx:AutolevParser.UnitFactorContext):
        pass


    # Enter a parse tree produced by AutolevParser#codeStatement.
    def enterCodeStatement(self, ctx:AutolevParser.CodeStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#codeStatement.
    def exitCodeStatement(self, ctx:AutolevParser.CodeStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#sweep.
    def enterSweep(self, ctx:AutolevParser.SweepContext):
        pass

    # Exit a parse tree produced by AutolevParser#sweep.
    def exitSweep(self, ctx:AutolevParser.SweepContext):
        pass


    # Enter a parse tree produced by AutolevParser#saveStatement.
    def enterSaveStatement(self, ctx:AutolevParser.SaveStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#saveStatement.
    def exitSaveStatement(self, ctx:AutolevParser.SaveStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#encodeStatement.
    def enterEncodeStatement(self, ctx:AutolevParser.EncodeStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#encodeStatement.
    def exitEncodeStatement(self, ctx:AutolevParser.EncodeStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#runStatement.
    def enterRunStatement(self, ctx:AutolevParser.RunStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#runStatement.
    def exitRunStatement(self, ctx:AutolevParser.RunStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#exitStatement.
    def enterExitStatement(self, ctx:AutolevParser.ExitStatementContext):
        pass

    # Exit a parse tree produced by AutolevParser#exitStatement.
    def exitExitStatement(self, ctx:AutolevParser.ExitStatementContext):
        pass


    # Enter a parse tree produced by AutolevParser#fileName.
    def enterFileName(self, ctx:AutolevParser.FileNameContext):
        pass

    # Exit a parse tree produced by AutolevParser#fileName.
    def exitFileName(self, ctx:AutolevParser.FileNameContext):
        pass


    # Enter a parse tree produced by AutolevParser#fileNamePart.
    def enterFileNamePart(self, ctx:AutolevParser.FileNamePartContext):
        pass

    # Exit a parse tree produced by AutolevParser#fileNamePart.
    def exitFileNamePart(self, ctx:AutolevParser.FileNamePartContext):
        pass


    # Enter a parse tree produced by AutolevParser#setting.
    def enterSetting(self, ctx:AutolevParser.SettingContext):
        pass

    # Exit a parse tree produced by AutolevParser#setting.
    def exitSetting(self, ctx:AutolevParser.SettingContext):
        pass


    # Enter a parse tree produced by AutolevParser#settingName.
    def enterSettingName(self, ctx:AutolevParser.SettingNameContext):
        pass

    # Exit a parse tree produced by AutolevParser#settingName.
    def exitSettingName(self, ctx:AutolevParser.SettingNameContext):
        pass


    # Enter a parse tree produced by AutolevParser#settingValue.
    def enterSettingValue(self, ctx:AutolevParser.SettingValueContext):
        pass

    # Exit a parse tree produced by AutolevParser#settingValue.
    def exitSettingValue(self, ctx:AutolevParser.SettingValueContext):
        pass


    # Enter a parse tree produced by AutolevParser#unaryExpr.
    def enterUnaryExpr(self, ctx:AutolevParser.UnaryExprContext):
        pass

    # Exit a parse tree produced by AutolevParser#unaryExpr.
    def exitUnaryExpr(self, ctx:AutolevParser.UnaryExprContext):
        pass


    # Enter a parse tree produced by AutolevParser#powerExpr.
    def enterPowerExpr(self, ctx:AutolevParser.PowerExprContext):
        pass

    # Exit a parse tree produced by AutolevParser#powerExpr.
    def exitPowerExpr(self, ctx:AutolevParser.PowerExprContext):
        pass


    # Enter a parse tree produced by AutolevParser#primaryExpr.
    def enterPrimaryExpr(self, ctx:AutolevParser.PrimaryExprContext):
        pass

    # Exit a parse tree produced by AutolevParser#primaryExpr.
    def exitPrimaryExpr(self, ctx:AutolevParser.PrimaryExprContext):
        pass


    # Enter a parse tree produced by AutolevParser#addExpr.
    def enterAddExpr(self, ctx:AutolevParser.AddExprContext):
        pass

    # Exit a parse tree produced by AutolevParser#addExpr.
    def exitAddExpr(self, ctx:AutolevParser.AddExprContext):
        pass


    # Enter a parse tree produced by AutolevParser#mulExpr.
    def enterMulExpr(self, ctx:AutolevParser.MulExprContext):
        pass

    # Exit a parse tree produced by AutolevParser#mulExpr.
    def exitMulExpr(self, ctx:AutolevParser.MulExprContext):
        pass


    # Enter a parse tree produced by AutolevParser#numberAtom.
    def enterNumberAtom(self, ctx:AutolevParser.NumberAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#numberAtom.
    def exitNumberAtom(self, ctx:AutolevParser.NumberAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#vectorAtom.
    def enterVectorAtom(self, ctx:AutolevParser.VectorAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#vectorAtom.
    def exitVectorAtom(self, ctx:AutolevParser.VectorAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#callAtom.
    def enterCallAtom(self, ctx:AutolevParser.CallAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#callAtom.
    def exitCallAtom(self, ctx:AutolevParser.CallAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#indexAtom.
    def enterIndexAtom(self, ctx:AutolevParser.IndexAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#indexAtom.
    def exitIndexAtom(self, ctx:AutolevParser.IndexAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#rangeAtom.
    def enterRangeAtom(self, ctx:AutolevParser.RangeAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#rangeAtom.
    def exitRangeAtom(self, ctx:AutolevParser.RangeAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#nameAtom.
    def enterNameAtom(self, ctx:AutolevParser.NameAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#nameAtom.
    def exitNameAtom(self, ctx:AutolevParser.NameAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#matrixAtom.
    def enterMatrixAtom(self, ctx:AutolevParser.MatrixAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#matrixAtom.
    def exitMatrixAtom(self, ctx:AutolevParser.MatrixAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#emptyMatrixAtom.
    def enterEmptyMatrixAtom(self, ctx:AutolevParser.EmptyMatrixAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#emptyMatrixAtom.
    def exitEmptyMatrixAtom(self, ctx:AutolevParser.EmptyMatrixAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#parenAtom.
    def enterParenAtom(self, ctx:AutolevParser.ParenAtomContext):
        pass

    # Exit a parse tree produced by AutolevParser#parenAtom.
    def exitParenAtom(self, ctx:AutolevParser.ParenAtomContext):
        pass


    # Enter a parse tree produced by AutolevParser#matrixRow.
    def enterMatrixRow(self, ctx:AutolevParser.MatrixRowContext):
        pass

    # Exit a parse tree produced by AutolevParser#matrixRow.
    def exitMatrixRow(self, ctx:AutolevParser.MatrixRowContext):
        pass


    # Enter a parse tree produced by AutolevParser#indexList.
    def enterIndexList(self, ctx:AutolevParser.IndexListContext):
        pass

    # Exit a parse tree produced by AutolevParser#indexList.
    def exitIndexList(self, ctx:AutolevParser.IndexListContext):
        pass


    # Enter a parse tree produced by AutolevParser#indexItem.
    def enterIndexItem(self, ctx:AutolevParser.IndexItemContext):
        pass

    # Exit a parse tree produced by AutolevParser#indexItem.
    def exitIndexItem(self, ctx:AutolevParser.IndexItemContext):
        pass


    # Enter a parse tree produced by AutolevParser#argList.
    def enterArgList(self, ctx:AutolevParser.ArgListContext):
        pass

    # Exit a parse tree produced by AutolevParser#argList.
    def exitArgList(self, ctx:AutolevParser.ArgListContext):
        pass


    # Enter a parse tree produced by AutolevParser#arg.
    def enterArg(self, ctx:AutolevParser.ArgContext):
        pass

    # Exit a parse tree produced by AutolevParser#arg.
    def exitArg(self, ctx:AutolevParser.ArgContext):
        pass


    # Enter a parse tree produced by AutolevParser#number.
    def enterNumber(self, ctx:AutolevParser.NumberContext):
        pass

    # Exit a parse tree produced by AutolevParser#number.
    def exitNumber(self, ctx:AutolevParser.NumberContext):
        pass


    # Enter a parse tree produced by AutolevParser#name.
    def enterName(self, ctx:AutolevParser.NameContext):
        pass

    # Exit a parse tree produced by AutolevParser#name.
    def exitName(self, ctx:AutolevParser.NameContext):
        pass



del AutolevParser