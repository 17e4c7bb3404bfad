<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE" sourcelanguage="en">
<context>
    <name>StudyInfo</name>
    <message>
        <location filename="../widgets/document/studyinfo.cpp" line="+16"/>
        <source>Setup correction</source>
        <translation>Einrichtdatenkorrektur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Posture matching</source>
        <translation>Lageausrichtung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kinematics &amp; SPC</source>
        <translation>Kinematik &amp; SPC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thermal</source>
        <translation>Thermik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diagnosis</source>
        <translation>Diagnose</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Computes corrections of the work offsets and tool offsets from CMM reports through the relation graph of machine points, work coordinate systems, tools, features and dimensions. It maximises the smallest error budget over all dimensions with the certified exact optimum (LP, then MILP on the 0.001 mm grid) and compares CRIPSO, PSO, GA and COA against it in convergence charts. Corrections export as the controller takes them.</source>
        <translation>Berechnet Korrekturen der Nullpunktverschiebungen und Werkzeugkorrekturen aus KMG-Messberichten über den Relationsgraphen aus Maschinenpunkten, Werkstückkoordinatensystemen, Werkzeugen, Formelementen und Maßen. Sie maximiert die kleinste Fehlerreserve über alle Maße mit dem nachweislich exakten Optimum (LP, dann MILP auf dem 0,001-mm-Raster) und vergleicht CRIPSO, PSO, GA und COA damit in Konvergenzdiagrammen. Die Korrekturen werden so exportiert, wie die Steuerung sie übernimmt.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Finds the actual posture of the workpiece from contact-probed points (nominal point, normal and measured point): rough matching from three reference points, fine matching by self-adaptive differential evolution, the closed-form least-squares optimum and a minimax tolerance-zone fit, then the adjustments of a 5-axis machine.</source>
        <translation>Bestimmt die tatsächliche Lage des Werkstücks aus angetasteten Punkten (Sollpunkt, Normale und Messpunkt): Grobausrichtung über drei Referenzpunkte, Feinausrichtung mit selbstadaptiver differentieller Evolution, das geschlossene Optimum der kleinsten Quadrate und eine Minimax-Anpassung an die Toleranzzone, danach die Einstellwerte einer 5-Achs-Maschine.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Identifies the actuator origin offsets and orientation errors (squareness) of a Cartesian machine from a circular test or a measured path, computes compensated references for a nominal path, and charts measured features with X-bar/R control limits, Cp and Cpk.</source>
        <translation>Identifiziert die Nullpunktversätze und Richtungsfehler (Rechtwinkligkeit) der Antriebe einer kartesischen Maschine aus einem Kreisformtest oder einer gemessenen Bahn, berechnet kompensierte Sollwerte für eine Nennbahn und stellt gemessene Merkmale in X-quer/R-Regelkarten mit Cp und Cpk dar.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Models the thermal displacement of the spindle from temperature sensors with the grey model GMC(1,N), the grey neural network GNNMCI(1,N) trained by PSO and an MLP, fitted on the first part of a log and tested on the rest; shows sensor trends and hysteresis.</source>
        <translation>Modelliert die thermische Verlagerung der Spindel aus Temperatursensoren mit dem Grey-Modell GMC(1,N), dem mit PSO trainierten grauen neuronalen Netz GNNMCI(1,N) und einem MLP, angepasst an den ersten Teil eines Protokolls und am Rest geprüft; zeigt Sensorverläufe und Hysterese.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Closes the loop: fits each declared model, looks at the residual it leaves, traces it to an effect the model lacks (thermal lag, an undeclared input, drift, backlash, scale, cyclic error, tool wear, surface offset and more), adds the effect only on strong out-of-sample evidence and reports the error before and after.</source>
        <translation>Schließt den Kreis: passt jedes deklarierte Modell an, untersucht das verbleibende Residuum, führt es auf einen Effekt zurück, der im Modell fehlt (thermische Verzögerung, eine nicht deklarierte Eingangsgröße, Drift, Umkehrspiel, Maßstab, zyklischer Fehler, Werkzeugverschleiß, Flächenversatz und mehr), nimmt den Effekt nur bei starker Bestätigung außerhalb der Stichprobe auf und zeigt den Fehler vorher und nachher.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Thermal log</source>
        <translation>Thermoprotokoll</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Probe points</source>
        <translation>Antastpunkte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Circular test</source>
        <translation>Kreisformtest</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CMM report</source>
        <translation>KMG-Messbericht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setup model</source>
        <translation>Einrichtmodell</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+21"/>
        <source>Metrofit — a workbench for machining error compensation.</source>
        <translation>Metrofit — eine Werkbank für die Kompensation von Bearbeitungsfehlern.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open the bundled demo project, save one PNG per main view into &lt;dir&gt; and exit (needs an X server; Xvfb will do).</source>
        <translation>Öffnet das mitgelieferte Demoprojekt, speichert je Hauptansicht ein PNG in &lt;dir&gt; und beendet sich (benötigt einen X-Server; Xvfb genügt).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>dir</source>
        <translation>verzeichnis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>project</source>
        <translation>projekt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A project file (.metrofit) to open.</source>
        <translation>Eine zu öffnende Projektdatei (.metrofit).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>[project]</source>
        <translation>[projekt]</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetTable</name>
    <message>
        <location filename="../app/gui/datasettable.cpp" line="+18"/>
        <source>Id</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Licence</source>
        <translation>Lizenz</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>File not found: %1</source>
        <translation>Datei nicht gefunden: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::FileChangedBar</name>
    <message>
        <location filename="../app/gui/filechangedbar.cpp" line="+20"/>
        <source>&amp;Reload</source>
        <translation>&amp;Neu laden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Ignore</source>
        <translation>&amp;Ignorieren</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The project file %1 was changed by another program.</source>
        <translation>Die Projektdatei %1 wurde von einem anderen Programm geändert.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The project file %1 was removed or renamed by another program.</source>
        <translation>Die Projektdatei %1 wurde von einem anderen Programm gelöscht oder umbenannt.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reloading discards your unsaved changes.</source>
        <translation>Beim Neuladen gehen Ihre ungespeicherten Änderungen verloren.</translation>
    </message>
</context>
<context>
    <name>metrofit::MainWindow</name>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="+42"/>
        <source>Metrofit projects (*.metrofit)</source>
        <translation>Metrofit-Projekte (*.metrofit)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Cannot export the report</source>
        <translation>Der Bericht kann nicht exportiert werden</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&amp;Overview</source>
        <translation>&amp;Übersicht</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open &amp;demo project</source>
        <translation>&amp;Demoprojekt öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Recent files</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+100"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export report PDF…</source>
        <translation>Bericht als PDF &amp;exportieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+6"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+7"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederherstellen: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Project &amp;navigator</source>
        <translation>Projekt&amp;navigator</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About Metrofit</source>
        <translation>Ü&amp;ber Metrofit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Project overview</source>
        <translation>Projektübersicht</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1[*] — Metrofit</source>
        <translation>%1[*] — Metrofit</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>No recent files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Clear list</source>
        <translation>Liste &amp;leeren</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot open the project</source>
        <translation>Das Projekt kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The project &quot;%1&quot; has unsaved changes. Do you want to save them?</source>
        <translation>Das Projekt „%1“ hat ungespeicherte Änderungen. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>New project</source>
        <translation>Neues Projekt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Open project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot open the demo project</source>
        <translation>Das Demoprojekt kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Demo project copied to %1</source>
        <translation>Demoprojekt nach %1 kopiert</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+20"/>
        <source>Cannot save the project</source>
        <translation>Das Projekt kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="-16"/>
        <location line="+21"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Save project as</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Export report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF-Dokumente (*.pdf)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Writing the report…</source>
        <translation>Der Bericht wird geschrieben…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The new language is applied at the next start.</source>
        <translation>Die neue Sprache wird beim nächsten Start übernommen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>About Metrofit</source>
        <translation>Über Metrofit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;Metrofit %1&lt;/h3&gt;&lt;p&gt;A workbench for machining error compensation: setup-data correction, posture matching, kinematic compensation with SPC, thermal error models, and the closed-loop diagnosis of what a model lacks.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later (GPL-3.0-or-later).&lt;/p&gt;&lt;p&gt;Built with Qt %2 (Qt Widgets, Qt Charts), VTK, Eigen %3 and GLPK.&lt;/p&gt;&lt;p&gt;The real thermal log of the demo project comes from the CAIVIAC data set and is used under the MIT licence.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Metrofit %1&lt;/h3&gt;&lt;p&gt;Eine Werkbank für die Kompensation von Bearbeitungsfehlern: Einrichtdatenkorrektur, Lageausrichtung, kinematische Kompensation mit SPC, thermische Fehlermodelle und die Diagnose im geschlossenen Kreis, die findet, was einem Modell fehlt.&lt;/p&gt;&lt;p&gt;Lizenziert unter der GNU General Public License, Version 3 oder später (GPL-3.0-or-later).&lt;/p&gt;&lt;p&gt;Erstellt mit Qt %2 (Qt Widgets, Qt Charts), VTK, Eigen %3 und GLPK.&lt;/p&gt;&lt;p&gt;Das reale Thermoprotokoll des Demoprojekts stammt aus dem CAIVIAC-Datensatz und wird unter der MIT-Lizenz verwendet.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>metrofit::MatchingPage</name>
    <message>
        <location filename="../app/gui/matchingpage.cpp" line="+57"/>
        <source>Point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Surface</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deviation before (mm)</source>
        <translation>Abweichung vorher (mm)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&amp;Probe points:</source>
        <translation>&amp;Antastpunkte:</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>This project has no probe points. Add a dataset of kind &quot;probe_points&quot; to the project file (id, surface, nominal point, normal, measured point).</source>
        <translation>Dieses Projekt hat keine Antastpunkte. Fügen Sie der Projektdatei einen Datensatz der Art „probe_points“ hinzu (Kennung, Fläche, Sollpunkt, Normale, Messpunkt).</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 points on %2 surfaces, %3. Before matching: RMS deviation %4 mm, largest %5 mm.</source>
        <translation>%1 Punkte auf %2 Flächen, %3. Vor der Ausrichtung: Effektivwert der Abweichung %4 mm, größte %5 mm.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>with normals</source>
        <translation>mit Normalen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>positions only</source>
        <translation>nur Positionen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Licence: %1.</source>
        <translation>Lizenz: %1.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot show these probe points:
%1</source>
        <translation>Diese Antastpunkte können nicht angezeigt werden:
%1</translation>
    </message>
</context>
<context>
    <name>metrofit::NotesEdit</name>
    <message>
        <location filename="../app/gui/notesedit.cpp" line="+10"/>
        <source>Notes on the %1 study (saved with the project)</source>
        <translation>Notizen zur Studie „%1“ (werden mit dem Projekt gespeichert)</translation>
    </message>
</context>
<context>
    <name>metrofit::OverviewPage</name>
    <message>
        <location filename="../app/gui/overviewpage.cpp" line="+23"/>
        <source>Project overview</source>
        <translation>Projektübersicht</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Project name</source>
        <translation>Projektname</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What is measured, on which machine, and why</source>
        <translation>Was wird gemessen, auf welcher Maschine und warum</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Description:</source>
        <translation>&amp;Beschreibung:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Datasets</source>
        <translation>Datensätze</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>not saved yet</source>
        <translation>noch nicht gespeichert</translation>
    </message>
</context>
<context>
    <name>metrofit::PreferencesDialog</name>
    <message>
        <location filename="../app/gui/preferencesdialog.cpp" line="+16"/>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The language is applied at the next start of Metrofit.</source>
        <translation>Die Sprache wird beim nächsten Start von Metrofit übernommen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>metrofit::ProjectDocument</name>
    <message>
        <location filename="../widgets/document/projectdocument.cpp" line="+30"/>
        <source>Rename project</source>
        <translation>Projekt umbenennen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edit project description</source>
        <translation>Projektbeschreibung bearbeiten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edit notes of %1</source>
        <translation>Notizen zu „%1“ bearbeiten</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>the project has not been saved yet; choose a file name with Save As</source>
        <translation>das Projekt wurde noch nicht gespeichert; wählen Sie mit „Speichern unter“ einen Dateinamen</translation>
    </message>
</context>
<context>
    <name>metrofit::ProjectNavigator</name>
    <message>
        <location filename="../app/gui/projectnavigator.cpp" line="+50"/>
        <location line="+11"/>
        <source>%1: project overview (Ctrl+1)</source>
        <translation>%1: Projektübersicht (Strg+1)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (Ctrl+%2)</source>
        <translation>%1 (Strg+%2)</translation>
    </message>
</context>
<context>
    <name>metrofit::ReportExporter</name>
    <message>
        <location filename="../app/gui/reportexporter.cpp" line="+51"/>
        <source>Cannot prepare the report: %1</source>
        <translation>Der Bericht kann nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Cannot run %1: %2</source>
        <translation>%1 kann nicht ausgeführt werden: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Writing the report…</source>
        <translation>Der Bericht wird geschrieben…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The report export was cancelled.</source>
        <translation>Der Berichtsexport wurde abgebrochen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>metrofit-cli stopped unexpectedly while writing %1.</source>
        <translation>metrofit-cli wurde beim Schreiben von %1 unerwartet beendet.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Report written to %1.</source>
        <translation>Bericht nach %1 geschrieben.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>metrofit-cli failed with exit code %1.</source>
        <translation>metrofit-cli ist mit dem Exit-Code %1 fehlgeschlagen.</translation>
    </message>
</context>
<context>
    <name>metrofit::StudyPage</name>
    <message>
        <location filename="../app/gui/studypage.cpp" line="+31"/>
        <source>The views of this study are not part of this version of the workbench yet. Nothing has been computed: the datasets it will work on are listed below.</source>
        <translation>Die Ansichten dieser Studie sind in dieser Version der Werkbank noch nicht enthalten. Es wurde nichts berechnet: Unten stehen die Datensätze, mit denen sie arbeiten wird.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>What this study does</source>
        <translation>Was diese Studie leistet</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Datasets</source>
        <translation>Datensätze</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>This project has no datasets for this study yet (it uses: %1).</source>
        <translation>Dieses Projekt hat noch keine Datensätze für diese Studie (sie verwendet: %1).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data this study uses: %1.</source>
        <translation>Daten, die diese Studie verwendet: %1.</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalPage</name>
    <message>
        <location filename="../app/gui/thermalpage.cpp" line="+48"/>
        <source>&amp;Thermal log:</source>
        <translation>&amp;Thermoprotokoll:</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>This project has no thermal log. Add a dataset of kind &quot;thermal_log&quot; to the project file (a time column, sensor columns and the displacement).</source>
        <translation>Dieses Projekt hat kein Thermoprotokoll. Fügen Sie der Projektdatei einen Datensatz der Art „thermal_log“ hinzu (eine Zeitspalte, Sensorspalten und die Verlagerung).</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 rows, %2 channels, %3 h.</source>
        <translation>%1 Zeilen, %2 Kanäle, %3 h.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Licence: %1.</source>
        <translation>Lizenz: %1.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot show this thermal log:
%1</source>
        <translation>Dieses Thermoprotokoll kann nicht angezeigt werden:
%1</translation>
    </message>
</context>
</TS>
