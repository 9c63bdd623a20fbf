"""The restricted arithmetic of values built from parameters, e.g. a blade's foot
`{0.4 - depth}` or a tooth's tip `{0.3 + 0.05 * cos(radians(angle))}`.

A template is the text an entry gets, with each `{expression}` replaced by its number.
Expressions are parsed into Python's syntax tree and only numbers, the parameters' names,
pi, + - * / % **, parentheses and the functions below are evaluated: user text is never
executed.
"""
import ast
import math
import operator
import re

FUNCTIONS = {
    'sin': math.sin, 'cos': math.cos, 'tan': math.tan, 'asin': math.asin, 'acos': math.acos,
    'atan': math.atan, 'atan2': math.atan2, 'sqrt': math.sqrt, 'exp': math.exp, 'log': math.log,
    'log10': math.log10, 'abs': abs, 'min': min, 'max': max, 'round': round, 'floor': math.floor,
    'ceil': math.ceil, 'radians': math.radians, 'degrees': math.degrees,
}
CONSTANTS = {'pi': math.pi}
BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
          ast.Div: operator.truediv, ast.Mod: operator.mod, ast.Pow: operator.pow}
UNARY = {ast.USub: operator.neg, ast.UAdd: operator.pos}
MAX_EXPONENT = 64   # keeps `10 ** 10 ** 10` from hanging the study


class ExpressionError(ValueError):
    pass


def evaluate(text, names):
    """The number `text` gives with the parameters `names` {name: number}."""
    try:
        tree = ast.parse(text.strip(), mode='eval')
    except SyntaxError:
        raise ExpressionError("'%s' is not an arithmetic expression" % text) from None
    try:
        return _value(tree.body, names, text)
    except (ArithmeticError, ValueError, TypeError) as e:
        if isinstance(e, ExpressionError):
            raise
        raise ExpressionError("'%s': %s" % (text, e)) from None


def _value(node, names, text):
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) \
            and not isinstance(node.value, bool):
        return node.value
    if isinstance(node, ast.Name):
        if node.id in names:
            value = names[node.id]
            if not isinstance(value, (int, float)):
                raise ExpressionError("'%s': parameter '%s' is not a number ('%s')" % (text, node.id, value))
            return value
        if node.id in CONSTANTS:
            return CONSTANTS[node.id]
        raise ExpressionError("'%s': unknown name '%s'; valid names: %s"
                              % (text, node.id, ', '.join(sorted(names) + sorted(CONSTANTS))))
    if isinstance(node, ast.BinOp) and type(node.op) in BINARY:
        left, right = _value(node.left, names, text), _value(node.right, names, text)
        if isinstance(node.op, ast.Pow) and abs(right) > MAX_EXPONENT:
            raise ExpressionError("'%s': exponent %g above %d" % (text, right, MAX_EXPONENT))
        if isinstance(node.op, ast.Pow):
            left = float(left)   # a float overflows with an error where an int grows without end
        return BINARY[type(node.op)](left, right)
    if isinstance(node, ast.UnaryOp) and type(node.op) in UNARY:
        return UNARY[type(node.op)](_value(node.operand, names, text))
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in FUNCTIONS \
            and not node.keywords:
        return FUNCTIONS[node.func.id](*[_value(a, names, text) for a in node.args])
    if isinstance(node, ast.Call):
        raise ExpressionError("'%s': unknown function; valid functions: %s" % (text, ', '.join(sorted(FUNCTIONS))))
    raise ExpressionError("'%s': only numbers, parameters, + - * / %% ** and functions are allowed" % text)


def format_number(value):
    """A number as an entry's text: 12 significant digits, so that 0.1 + 2 x 0.05 writes 0.2."""
    if isinstance(value, bool):
        raise ExpressionError('a truth value where a number is expected')
    if isinstance(value, int):
        return str(value)
    if value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return '%.12g' % value


def format_value(value):
    """A parameter's value as an entry's text: a number, a word, or a list in parentheses."""
    if isinstance(value, (list, tuple)):
        return '(' + ' '.join(format_value(v) for v in value) + ')'
    if isinstance(value, (int, float)):
        return format_number(value)
    return str(value)


def fill(template, names):
    """The template's text with each {expression} replaced by its formatted number."""
    if template.count('{') != template.count('}'):
        raise ExpressionError("'%s': unbalanced braces" % template)
    return re.sub(r'\{([^{}]*)\}', lambda m: format_number(evaluate(m.group(1), names)), template)
