# Generated from grammar/Autolev.g4 by ANTLR 4.13.2
from antlr4 import *
if "." in __name__:
    from .AutolevParser import AutolevParser
else:
    from AutolevParser import AutolevParser

# This class defines a complete generic visitor for a parse tree produced by AutolevParser.

class AutolevVisitor(ParseTreeVisitor):

    # Visit a parse tree produced by AutolevParser#program.
    def visitProgram(self, ctx:AutolevParser.ProgramContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#singleLine.
    def visitSingleLine(self, ctx:AutolevParser.SingleLineContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#statementLine.
    def visitStatementLine(self, ctx:AutolevParser.StatementLineContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#statement.
    def visitStatement(self, ctx:AutolevParser.StatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declaration.
    def visitDeclaration(self, ctx:AutolevParser.DeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declKeyword.
    def visitDeclKeyword(self, ctx:AutolevParser.DeclKeywordContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declarator.
    def visitDeclarator(self, ctx:AutolevParser.DeclaratorContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declRange.
    def visitDeclRange(self, ctx:AutolevParser.DeclRangeContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#rangeBound.
    def visitRangeBound(self, ctx:AutolevParser.RangeBoundContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declSign.
    def visitDeclSign(self, ctx:AutolevParser.DeclSignContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#massStatement.
    def visitMassStatement(self, ctx:AutolevParser.MassStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#massItem.
    def visitMassItem(self, ctx:AutolevParser.MassItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inertiaStatement.
    def visitInertiaStatement(self, ctx:AutolevParser.InertiaStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inertiaValue.
    def visitInertiaValue(self, ctx:AutolevParser.InertiaValueContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#assignment.
    def visitAssignment(self, ctx:AutolevParser.AssignmentContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#vectorTarget.
    def visitVectorTarget(self, ctx:AutolevParser.VectorTargetContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#scalarTarget.
    def visitScalarTarget(self, ctx:AutolevParser.ScalarTargetContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#assignOp.
    def visitAssignOp(self, ctx:AutolevParser.AssignOpContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#expressionStatement.
    def visitExpressionStatement(self, ctx:AutolevParser.ExpressionStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inputStatement.
    def visitInputStatement(self, ctx:AutolevParser.InputStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inputItem.
    def visitInputItem(self, ctx:AutolevParser.InputItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#outputStatement.
    def visitOutputStatement(self, ctx:AutolevParser.OutputStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#outputItem.
    def visitOutputItem(self, ctx:AutolevParser.OutputItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unitsStatement.
    def visitUnitsStatement(self, ctx:AutolevParser.UnitsStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unitsItem.
    def visitUnitsItem(self, ctx:AutolevParser.UnitsItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unitsTarget.
    def visitUnitsTarget(self, ctx:AutolevParser.UnitsTargetContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unitSystemStatement.
    def visitUnitSystemStatement(self, ctx:AutolevParser.UnitSystemStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unit.
    def visitUnit(self, ctx:AutolevParser.UnitContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unitFactor.
    def visitUnitFactor(self, ctx:AutolevParser.UnitFactorContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#codeStatement.
    def visitCodeStatement(self, ctx:AutolevParser.CodeStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#sweep.
    def visitSweep(self, ctx:AutolevParser.SweepContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#saveStatement.
    def visitSaveStatement(self, ctx:AutolevParser.SaveStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#encodeStatement.
    def visitEncodeStatement(self, ctx:AutolevParser.EncodeStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#runStatement.
    def visitRunStatement(self, ctx:AutolevParser.RunStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#exitStatement.
    def visitExitStatement(self, ctx:AutolevParser.ExitStatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#fileName.
    def visitFileName(self, ctx:AutolevParser.FileNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#fileNamePart.
    def visitFileNamePart(self, ctx:AutolevParser.FileNamePartContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#setting.
    def visitSetting(self, ctx:AutolevParser.SettingContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#settingName.
    def visitSettingName(self, ctx:AutolevParser.SettingNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#settingValue.
    def visitSettingValue(self, ctx:AutolevParser.SettingValueContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unaryExpr.
    def visitUnaryExpr(self, ctx:AutolevParser.UnaryExprContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#powerExpr.
    def visitPowerExpr(self, ctx:AutolevParser.PowerExprContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#primaryExpr.
    def visitPrimaryExpr(self, ctx:AutolevParser.PrimaryExprContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#addExpr.
    def visitAddExpr(self, ctx:AutolevParser.AddExprContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#mulExpr.
    def visitMulExpr(self, ctx:AutolevParser.MulExprContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#numberAtom.
    def visitNumberAtom(self, ctx:AutolevParser.NumberAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#vectorAtom.
    def visitVectorAtom(self, ctx:AutolevParser.VectorAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#callAtom.
    def visitCallAtom(self, ctx:AutolevParser.CallAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#indexAtom.
    def visitIndexAtom(self, ctx:AutolevParser.IndexAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#rangeAtom.
    def visitRangeAtom(self, ctx:AutolevParser.RangeAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#nameAtom.
    def visitNameAtom(self, ctx:AutolevParser.NameAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#matrixAtom.
    def visitMatrixAtom(self, ctx:AutolevParser.MatrixAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#emptyMatrixAtom.
    def visitEmptyMatrixAtom(self, ctx:AutolevParser.EmptyMatrixAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#parenAtom.
    def visitParenAtom(self, ctx:AutolevParser.ParenAtomContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#matrixRow.
    def visitMatrixRow(self, ctx:AutolevParser.MatrixRowContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#indexList.
    def visitIndexList(self, ctx:AutolevParser.IndexListContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#indexItem.
    def visitIndexItem(self, ctx:AutolevParser.IndexItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#argList.
    def visitArgList(self, ctx:AutolevParser.ArgListContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#arg.
    def visitArg(self, ctx:AutolevParser.ArgContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#number.
    def visitNumber(self, ctx:AutolevParser.NumberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#name.
    def visitName(self, ctx:AutolevParser.NameContext):
        return self.visitChildren(ctx)



del AutolevParser