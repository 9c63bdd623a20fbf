"""The one error a user's input can cause: printed as one line naming file, line and keyword,
as the project's applications do, with exit status 1."""


class InputError(Exception):
    def __init__(self, path, line, message):
        self.path, self.line = path, line
        super().__init__('%s:%s: %s' % (path, line, message) if line else '%s: %s' % (path, message))


def choices(words):
    """'a, b, c' for an error's list of valid choices."""
    return ', '.join(words) if words else '(none)'
