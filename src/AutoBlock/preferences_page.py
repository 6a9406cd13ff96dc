"""The preferences page (Edit > Preferences > AutoBlock), from resources/ui/preferences.ui.

The page uses FreeCAD's Pref widgets (their prefEntry names are the parameters of preferences.py), but
loads and saves them itself: the policy and reward lists come from the core, and choices are stored by
name (FreeCAD's PrefComboBox would store an index, which breaks when the core's list grows).
"""

import FreeCADGui

from . import paths, preferences


# How the reward preset "" (the core's default: each policy's own) reads in the list.
OWN_PRESET = "each policy's own"


class AutoBlockPreferencesPage:
    def __init__(self, parent=None):
        self.form = FreeCADGui.PySideUic.loadUi(paths.ui("preferences"))
        self.available = True
        self.default_policy = ""
        try:
            from . import native

            module = native.load()
            self.policies = list(module.policy_names())
            self.presets = [""] + [p for p in module.reward_presets() if p]
            self.default_policy = module.default_policy()
            capabilities = dict(module.capabilities())
        except Exception as error:
            self.available = False
            self.policies, self.presets, capabilities = [], [], {}
            self.form.noteLabel.setText("The AutoBlock native module is not available: {}".format(error))
        self.form.defaultPolicy.addItems(self.policies)
        self.form.rewardPreset.addItems([p or OWN_PRESET for p in self.presets])
        notes = []
        if self.default_policy:
            notes.append("without a choice here, new AutoBlock objects use the core's default policy, {}".format(
                self.default_policy))
        if not capabilities.get("learned_policies"):
            notes.append("policy files need learned policies, which this build does not have")
        if not capabilities.get("meshing"):
            notes.append("this build cannot mesh: the mesh size is only stored")
        if notes and self.available:
            self.form.noteLabel.setText("Note: " + "; ".join(notes) + ".")

    def loadSettings(self):
        p = preferences.params()
        f = self.form
        policy = p.GetString(preferences.DEFAULT_POLICY, "") or self.default_policy
        if policy in self.policies:
            f.defaultPolicy.setCurrentIndex(self.policies.index(policy))
        f.defaultPolicyFile.setProperty("fileName", p.GetString(preferences.DEFAULT_POLICY_FILE, ""))
        preset = p.GetString(preferences.REWARD_PRESET, "")
        if preset in self.presets:
            f.rewardPreset.setCurrentIndex(self.presets.index(preset))
        f.meshSize.setValue(p.GetFloat(preferences.MESH_SIZE, 0.0))
        f.threads.setValue(p.GetInt(preferences.THREADS, 0))
        f.capFace.setCurrentIndex(preferences.CAP_FACE_CHOICES.index(preferences.cap_face()))

    def saveSettings(self):
        p = preferences.params()
        f = self.form
        if self.policies:
            p.SetString(preferences.DEFAULT_POLICY, f.defaultPolicy.currentText())
        p.SetString(preferences.DEFAULT_POLICY_FILE, str(f.defaultPolicyFile.property("fileName") or ""))
        if self.presets and f.rewardPreset.currentIndex() >= 0:
            p.SetString(preferences.REWARD_PRESET, self.presets[f.rewardPreset.currentIndex()])
        p.SetFloat(preferences.MESH_SIZE, float(f.meshSize.value()))
        p.SetInt(preferences.THREADS, int(f.threads.value()))
        if f.capFace.currentIndex() >= 0:
            p.SetString(preferences.CAP_FACE, preferences.CAP_FACE_CHOICES[f.capFace.currentIndex()])


_registered = False


def register():
    global _registered
    if not _registered:
        FreeCADGui.addPreferencePage(AutoBlockPreferencesPage, "AutoBlock")
        _registered = True
