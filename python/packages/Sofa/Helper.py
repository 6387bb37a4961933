"""Sofa.Helper: messages, message handlers and the data repository."""
import os

import _sinew

msg_info = _sinew.msg_info
msg_warning = _sinew.msg_warning
msg_error = _sinew.msg_error
msg_deprecated = _sinew.msg_deprecated
msg_fatal = _sinew.msg_fatal

_handlers = []


class MessageHandler:
    """Receives every message while in use (``with handler:``); override process(msg).

    ``msg`` is a dict with ``type`` ("Info", "Warning" or "Error"), ``sender``,
    ``message`` and ``fileInfo``.
    """

    def __init__(self):
        pass

    def process(self, msg):
        pass

    def __enter__(self):
        _handlers.append(self)
        _sinew._set_message_sinks(list(_handlers))
        return self

    def __exit__(self, *exc):
        if self in _handlers:
            _handlers.remove(self)
        _sinew._set_message_sinks(list(_handlers))
        return False


class _DataRepository:
    """Folders searched for meshes and other resources (SOFA's DataRepository)."""

    def addFirstPath(self, path):
        _sinew.add_data_path(os.path.abspath(path), True)

    def addLastPath(self, path):
        _sinew.add_data_path(os.path.abspath(path), False)

    def removePath(self, path):
        _sinew.remove_data_path(os.path.abspath(path))

    def getPaths(self):
        return list(_sinew.data_paths())

    def getPathsJoined(self):
        return ":".join(self.getPaths())

    def findFile(self, name):
        if os.path.isabs(name):
            return os.path.exists(name)
        return any(os.path.exists(os.path.join(p, name)) for p in self.getPaths())

    def getFile(self, name):
        if os.path.isabs(name):
            return name
        for p in self.getPaths():
            f = os.path.join(p, name)
            if os.path.exists(f):
                return f
        return name


class System:
    DataRepository = _DataRepository()
