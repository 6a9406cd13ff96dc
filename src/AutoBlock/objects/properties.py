"""Properties of FeaturePython objects, declared as tables and added where missing (new objects, and
objects restored from documents saved by an older version)."""


def ensure_properties(obj, properties, read_only=(), hidden=()):
    """Add every (type, name, group, tooltip, attributes) of properties that obj lacks; set the
    editor modes: read-only for the names in read_only, hidden for those in hidden."""
    for kind, name, group, tooltip, attributes in properties:
        if name not in obj.PropertiesList:
            obj.addProperty(kind, name, group, tooltip, attributes)
    for name in read_only:
        obj.setEditorMode(name, 1)
    for name in hidden:
        obj.setEditorMode(name, 2)
