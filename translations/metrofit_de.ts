<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE" sourcelanguage="en">
<context>
    <name>StudyInfo</name>
    <message>
        <location filename="../widgets/document/studyinfo.cpp" line="+18"/>
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
        <location line="+29"/>
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
    <message>
        <location line="+2"/>
        <source>SPC feature series</source>
        <translation>SPC-Merkmalsreihe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>DMIS output</source>
        <translation>DMIS-Ausgabe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hole table</source>
        <translation>Bohrungstabelle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Q-DAS DFQ file</source>
        <translation>Q-DAS-DFQ-Datei</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zeiss Calypso table</source>
        <translation>Zeiss-Calypso-Tabelle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAD part (STL)</source>
        <translation>CAD-Teil (STL)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>QIF results</source>
        <translation>QIF-Ergebnisse</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MTConnect log</source>
        <translation>MTConnect-Protokoll</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+23"/>
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
        <location line="+3"/>
        <source>User interface language for this run: en, de or pl (overrides the Preferences; the screenshots are in English without it).</source>
        <translation>Sprache der Benutzeroberfläche für diesen Start: en, de oder pl (hat Vorrang vor den Einstellungen; ohne diese Option sind die Screenshots auf Englisch).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>language</source>
        <translation>sprache</translation>
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
    <name>metrofit::Autosave</name>
    <message>
        <location filename="../app/gui/autosave.cpp" line="+186"/>
        <source>cannot create the autosave folder %1</source>
        <translation>der Ordner für die automatische Sicherung %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+69"/>
        <location line="+60"/>
        <source>The autosaved copy cannot be read: %1</source>
        <translation>Die automatisch gesicherte Kopie kann nicht gelesen werden: %1</translation>
    </message>
    <message>
        <location line="-44"/>
        <location line="+54"/>
        <location line="+52"/>
        <source>Recover autosaved changes</source>
        <translation>Automatisch gesicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <location line="-23"/>
        <source>An autosaved edit cannot be recovered: %1</source>
        <translation>Eine automatisch gesicherte Änderung kann nicht wiederhergestellt werden: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Metrofit was not closed properly. An autosaved copy of the unsaved project “%1” from %2 was found.

Do you want to recover it?</source>
        <translation>Metrofit wurde nicht ordnungsgemäß beendet. Eine automatisch gesicherte Kopie des ungespeicherten Projekts „%1“ vom %2 wurde gefunden.

Möchten Sie sie wiederherstellen?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The project %1 has an autosaved copy from %2 that is newer than the file (saved %3). Metrofit was probably not closed properly.

Do you want to recover the autosaved changes? They are opened as unsaved changes; the project file is only overwritten when you save.</source>
        <translation>Zum Projekt %1 gibt es eine automatisch gesicherte Kopie vom %2, die neuer ist als die Datei (gespeichert %3). Metrofit wurde wahrscheinlich nicht ordnungsgemäß beendet.

Möchten Sie die automatisch gesicherten Änderungen wiederherstellen? Sie werden als ungespeicherte Änderungen geöffnet; die Projektdatei wird erst beim Speichern überschrieben.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The autosaved copy includes unsaved edits of the setup model (relation graph); they are recovered as unsaved edits too.</source>
        <translation>Die automatisch gesicherte Kopie enthält ungespeicherte Änderungen am Einrichtmodell (Beziehungsgraph); sie werden ebenfalls als ungespeicherte Änderungen wiederhergestellt.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Keep for later</source>
        <translation>&amp;Für später behalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Open original</source>
        <translation>&amp;Original öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open the autosaved content as unsaved changes</source>
        <translation>Den automatisch gesicherten Inhalt als ungespeicherte Änderungen öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete the autosaved copy</source>
        <translation>Die automatisch gesicherte Kopie löschen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Leave the autosaved copy where it is and continue without it</source>
        <translation>Die automatisch gesicherte Kopie belassen und ohne sie fortfahren</translation>
    </message>
</context>
<context>
    <name>metrofit::BackgroundRunBase</name>
    <message>
        <location filename="../widgets/common/backgroundrun.cpp" line="+112"/>
        <source>unknown error</source>
        <translation>unbekannter Fehler</translation>
    </message>
</context>
<context>
    <name>metrofit::BallbarText</name>
    <message>
        <location filename="../widgets/kinematics/ballbartext.cpp" line="+30"/>
        <source>Backlash %1</source>
        <translation>Umkehrspiel %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reversal spikes %1</source>
        <translation>Umkehrspitzen %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lateral play %1</source>
        <translation>Seitliches Spiel %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Straightness %1</source>
        <translation>Geradheit %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cyclic error %1</source>
        <translation>Zyklischer Fehler %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Servo mismatch</source>
        <translation>Servo-Fehlanpassung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scale mismatch</source>
        <translation>Maßstabsabweichung X/Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Squareness</source>
        <translation>Rechtwinkligkeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unexplained (RMS)</source>
        <translation>Nicht erklärt (RMS)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Lost motion of the %1 axis at its reversals: the axis lags half of it behind its direction of motion</source>
        <translation>Lose der %1-Achse an ihren Umkehrpunkten: die Achse bleibt um die Hälfte davon hinter ihrer Bewegungsrichtung zurück</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Peak of a short lag of the %1 axis after each reversal, decaying over about 2° of the path; positive: outwards</source>
        <translation>Spitzenwert eines kurzen Nachlaufs der %1-Achse nach jeder Umkehr, abklingend über etwa 2° der Bahn; positiv: nach außen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Sideways step of the %1 carriage when its axis reverses</source>
        <translation>Seitlicher Versatz des %1-Schlittens, wenn seine Achse umkehrt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bow of the %1 axis across the test diameter (its middle relative to its ends)</source>
        <translation>Durchbiegung der %1-Achse über den Testdurchmesser (ihre Mitte gegenüber ihren Enden)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Amplitude of the periodic error of the %1 axis with the screw pitch</source>
        <translation>Amplitude des periodischen Fehlers der %1-Achse mit der Spindelsteigung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Difference of the X and Y following errors at the test&apos;s feed; positive: X lags more</source>
        <translation>Unterschied der Schleppfehler von X und Y beim Vorschub des Tests; positiv: X läuft stärker nach</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(Scale of X − scale of Y) × radius; positive: X travels further than Y</source>
        <translation>(Maßstab von X − Maßstab von Y) × Radius; positiv: X fährt weiter als Y</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Squareness error (b − a) × radius: the shear over the test radius</source>
        <translation>Rechtwinkligkeitsfehler (b − a) × Radius: die Scherung über den Testradius</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RMS of what the causes leave: noise and errors not in the list</source>
        <translation>RMS dessen, was die Ursachen übrig lassen: Rauschen und Fehler, die nicht in der Liste stehen</translation>
    </message>
</context>
<context>
    <name>metrofit::ChartExport</name>
    <message>
        <location filename="../widgets/common/chartexport.cpp" line="+137"/>
        <source>Export chart as SVG</source>
        <translation>Diagramm als SVG exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Export chart as PNG</source>
        <translation>Diagramm als PNG exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SVG drawings (*.svg)</source>
        <translation>SVG-Zeichnungen (*.svg)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Chart exported to %1</source>
        <translation>Diagramm nach %1 exportiert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cannot export the chart: %1</source>
        <translation>Das Diagramm kann nicht exportiert werden: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export as &amp;PNG…</source>
        <translation>Als &amp;PNG exportieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save this chart as a PNG image (the size it has on screen)</source>
        <translation>Dieses Diagramm als PNG-Bild speichern (in seiner Größe auf dem Bildschirm)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export as &amp;SVG…</source>
        <translation>Als &amp;SVG exportieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save this chart as an SVG drawing (lines and text stay sharp)</source>
        <translation>Dieses Diagramm als SVG-Zeichnung speichern (Linien und Text bleiben scharf)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Copy image</source>
        <translation>Bild &amp;kopieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Chart copied to the clipboard</source>
        <translation>Diagramm in die Zwischenablage kopiert</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>the chart has no picture to export</source>
        <translation>das Diagramm enthält kein Bild zum Exportieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+21"/>
        <location line="+11"/>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location line="-24"/>
        <source>a 3D view can only be exported as PNG</source>
        <translation>eine 3D-Ansicht kann nur als PNG exportiert werden</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Exported from Metrofit</source>
        <translation>Aus Metrofit exportiert</translation>
    </message>
</context>
<context>
    <name>metrofit::ChartNavigation</name>
    <message>
        <location filename="../widgets/common/chartnavigation.cpp" line="+139"/>
        <location filename="../widgets/common/plotnavigation.cpp" line="+46"/>
        <source>&amp;Reset zoom (double click, Home)</source>
        <translation>&amp;Zoom zurücksetzen (Doppelklick, Pos1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../widgets/common/plotnavigation.cpp" line="+2"/>
        <source>Show the whole chart again</source>
        <translation>Das ganze Diagramm wieder zeigen</translation>
    </message>
</context>
<context>
    <name>metrofit::CircularPathView</name>
    <message>
        <location filename="../widgets/kinematics/kinematicsviews.cpp" line="+60"/>
        <source>point %1 (%2)
x: %3 mm, y: %4 mm
radial deviation: %5 µm</source>
        <translation>Punkt %1 (%2)
x: %3 mm; y: %4 mm
radiale Abweichung: %5 µm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CCW</source>
        <translation>GUZ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CW</source>
        <translation>UZ</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The XY path in mm: the nominal circle true to scale; the measured path, the compensated references and the expected result as deviations from the nominal point, magnified by the factor shown.</source>
        <translation>Die XY-Bahn in mm: der Nennkreis maßstabsgetreu; die gemessene Bahn, die kompensierten Sollwerte und das erwartete Ergebnis als Abweichungen vom Nennpunkt, vergrößert um den angegebenen Faktor.</translation>
    </message>
</context>
<context>
    <name>metrofit::ControlChartView</name>
    <message>
        <location line="+89"/>
        <source>subgroup %1
mean: %2%3</source>
        <translation>Untergruppe %1
Mittelwert: %2%3</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>subgroup %1
range: %2%3</source>
        <translation>Untergruppe %1
Spannweite: %2%3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Subgroup means with the centre line and the control limits UCL/LCL = mean ± A2 · R̄ (kinematic-compensation paper, Eq. 18–19); red points are out of control, ringed ones break a Nelson rule (the read-out names it).</source>
        <translation>Stichprobenmittelwerte mit Mittellinie und Eingriffsgrenzen OEG/UEG = Mittelwert ± A2 · R̄ (Kinematik-Kompensationsartikel, Gl. 18–19); rote Punkte liegen außerhalb der Grenzen, umringte verletzen eine Nelson-Regel (die Anzeige nennt sie).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Subgroup ranges with the centre line R̄ and the limits D4 · R̄ and D3 · R̄.</source>
        <translation>Spannweiten der Untergruppen mit der Mittellinie R̄ und den Grenzen D4 · R̄ und D3 · R̄.</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetActions</name>
    <message>
        <location filename="../app/gui/datasetactions.cpp" line="+55"/>
        <source>%1 — data</source>
        <translation>%1 — Daten</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>&amp;Show data</source>
        <translation>Daten &amp;zeigen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Rename dataset…</source>
        <translation>Datensatz &amp;umbenennen…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Re-&amp;link to a moved file…</source>
        <translation>Mit verschobener Datei neu &amp;verknüpfen…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Re&amp;move dataset</source>
        <translation>Datensatz &amp;entfernen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Remove the dataset “%1” from the project? The file itself stays where it is.</source>
        <translation>Den Datensatz „%1“ aus dem Projekt entfernen? Die Datei selbst bleibt, wo sie ist.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>These study settings name it and are removed with it: %1</source>
        <translation>Diese Studieneinstellungen nennen ihn und werden mit ihm entfernt: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove dataset</source>
        <translation>Datensatz entfernen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot remove the dataset</source>
        <translation>Der Datensatz kann nicht entfernt werden</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Rename dataset</source>
        <translation>Datensatz umbenennen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New id of “%1” (study settings that name it follow):</source>
        <translation>Neue Kennung für „%1“ (Studieneinstellungen, die ihn nennen, werden angepasst):</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot rename the dataset</source>
        <translation>Der Datensatz kann nicht umbenannt werden</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Re-link the %1 files of the series “%2”</source>
        <translation>Die %1 Dateien der Serie „%2“ neu verknüpfen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Re-link dataset “%1”</source>
        <translation>Datensatz „%1“ neu verknüpfen</translation>
    </message>
    <message>
        <location line="-3"/>
        <location line="+4"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot re-link the dataset</source>
        <translation>Der Datensatz kann nicht neu verknüpft werden</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetTable</name>
    <message>
        <location filename="../app/gui/datasettable.cpp" line="+23"/>
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
        <location line="+48"/>
        <source>File not found: %1</source>
        <translation>Datei nicht gefunden: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetTableModel</name>
    <message>
        <location filename="../widgets/data/datasettablemodel.cpp" line="+139"/>
        <source>out of tolerance</source>
        <translation>außer Toleranz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no tolerance</source>
        <translation>keine Toleranz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>in tolerance</source>
        <translation>in Toleranz</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Line %1 of the file</source>
        <translation>Zeile %1 der Datei</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Deviation %1 %2 is outside the tolerance %3 … %4</source>
        <translation>Abweichung %1 %2 liegt außerhalb der Toleranz %3 … %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The report marks this value out of tolerance</source>
        <translation>Der Bericht markiert diesen Wert als außer Toleranz</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Part</source>
        <translation>Teil</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Feature</source>
        <translation>Merkmal</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Characteristic</source>
        <translation>Kenngröße</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nominal</source>
        <translation>Nennwert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Actual</source>
        <translation>Istwert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Deviation</source>
        <translation>Abweichung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lower tol.</source>
        <translation>Untere Tol.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Upper tol.</source>
        <translation>Obere Tol.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The file&apos;s column “%1”, read as %2</source>
        <translation>Spalte „%1“ der Datei, gelesen als %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The file&apos;s column “%1”</source>
        <translation>Spalte „%1“ der Datei</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Actual − nominal (plain sign; OGP prints locations with the sign of the nominal)</source>
        <translation>Ist − Soll (einfaches Vorzeichen; OGP druckt Lagen mit dem Vorzeichen des Nennwerts)</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetView</name>
    <message>
        <location filename="../widgets/data/datasetview.cpp" line="+108"/>
        <source>Filter rows (text in any column)</source>
        <translation>Zeilen filtern (Text in einer beliebigen Spalte)</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>&amp;Filter:</source>
        <translation>&amp;Filter:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Plot:</source>
        <translation>&amp;Diagramm:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;against</source>
        <translation>ge&amp;gen</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Reading %1…</source>
        <translation>Lese %1 …</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Cannot show %1: %2</source>
        <translation>%1 kann nicht angezeigt werden: %2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>row number</source>
        <translation>Zeilennummer</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Deviation</source>
        <translation>Abweichung</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1, %2 rows</source>
        <translation>%1, %2 Zeilen</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n out of tolerance</source>
        <translation>
            <numerusform>%n außer Toleranz</numerusform>
            <numerusform>%n außer Toleranz</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 shown</source>
        <translation>%1 angezeigt</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>row</source>
        <translation>Zeile</translation>
    </message>
</context>
<context>
    <name>metrofit::DiagnosisPage</name>
    <message>
        <location filename="../app/gui/diagnosispage.cpp" line="+75"/>
        <source>Thermal</source>
        <translation>Thermik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kinematic</source>
        <translation>Kinematik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setup</source>
        <translation>Einrichtung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Matching</source>
        <translation>Ausrichtung</translation>
    </message>
    <message>
        <location line="+653"/>
        <source>Apply diagnosed effects (%1)</source>
        <translation>Diagnostizierte Effekte übernehmen (%1)</translation>
    </message>
    <message>
        <location line="-549"/>
        <source>&amp;Run</source>
        <translation>A&amp;usführen</translation>
    </message>
    <message>
        <location line="-86"/>
        <source>mm/part</source>
        <translation>mm/Werkstück</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Apply to model</source>
        <translation>Ins &amp;Modell übernehmen</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>The study whose declared model is diagnosed</source>
        <translation>Die Studie, deren deklariertes Modell diagnostiziert wird</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fit the declared model, try the candidate effects it lacks, accept those the evidence supports (Ctrl+R)</source>
        <translation>Das deklarierte Modell anpassen, die fehlenden Kandidateneffekte testen und die durch die Evidenz gestützten übernehmen (Strg+R)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stop the loop; the rounds done so far are shown (Esc)</source>
        <translation>Die Schleife anhalten; die bisherigen Runden werden angezeigt (Esc)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+341"/>
        <source>Add the accepted effects to the study&apos;s model in the project (undoable, Ctrl+Shift+A)</source>
        <translation>Die übernommenen Effekte dem Modell der Studie im Projekt hinzufügen (rückgängig machbar, Strg+Umschalt+A)</translation>
    </message>
    <message>
        <location line="-327"/>
        <source>The declared model as fitted before any effect was added</source>
        <translation>Das deklarierte Modell, wie es vor dem Hinzufügen eines Effekts angepasst wurde</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The effect whose residual plot is shown</source>
        <translation>Der Effekt, dessen Residuendiagramm angezeigt wird</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Residual &amp;plot of:</source>
        <translation>Residuendia&amp;gramm von:</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Round</source>
        <translation>Runde</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Effect</source>
        <translation>Effekt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parameters (± standard error)</source>
        <translation>Parameter (± Standardfehler)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rmse before → after</source>
        <translation>rmse vorher → nachher</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>held-out rmse</source>
        <translation>rmse Testdaten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Evidence</source>
        <translation>Evidenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accepted</source>
        <translation>Übernommen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Every candidate effect tried, in the order tried (Ctrl+C copies the selected rows)</source>
        <translation>Alle getesteten Kandidateneffekte in der Reihenfolge des Tests (Strg+C kopiert die ausgewählten Zeilen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Effects</source>
        <translation>&amp;Effekte</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+191"/>
        <location line="+114"/>
        <source>Residual chec&amp;k</source>
        <translation>Residuen&amp;prüfung</translation>
    </message>
    <message>
        <location line="-303"/>
        <source>The candidate effects tried, their residual plots and the error before / after</source>
        <translation>Die getesteten Kandidateneffekte, ihre Residuendiagramme und der Fehler vorher / nachher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>What the final residual still depends on: tests, structure, outliers and the residual against the variable of the strongest structure</source>
        <translation>Wovon das endgültige Residuum noch abhängt: Tests, Struktur, Ausreißer und das Residuum über der Variablen der stärksten Struktur</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Domain:</source>
        <translation>Ber&amp;eich:</translation>
    </message>
    <message>
        <location line="+52"/>
        <location line="+156"/>
        <source>The diagnosis failed: %1</source>
        <translation>Die Diagnose ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>Data: %1</source>
        <translation>Daten: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>; target %1; declared inputs %2; fitted on the first %3 % of the rows, held out on the rest.</source>
        <translation>; Zielgröße %1; deklarierte Eingänge %2; angepasst an den ersten %3 % der Zeilen, der Rest dient als Testdaten.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>; declared model: Cartesian actuator errors (origin, axis angles); feed %1 mm/min.</source>
        <translation>; deklariertes Modell: kartesische Antriebsfehler (Ursprung, Achswinkel); Vorschub %1 mm/min.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>; setup model %1; declared model: constant setup-data errors.</source>
        <translation>; Einrichtmodell %1; deklariertes Modell: konstante Einrichtdatenfehler.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>; declared model: rigid posture; tolerance ±%1 mm.</source>
        <translation>; deklariertes Modell: starre Lage; Toleranz ±%1 mm.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Applied to the model: %1.</source>
        <translation>Ins Modell übernommen: %1.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Not run yet: press Run (Ctrl+R).</source>
        <translation>Noch nicht ausgeführt: Ausführen drücken (Strg+R).</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Diagnosing …</source>
        <translation>Diagnose läuft …</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Diagnosing … step %1, current rmse %2</source>
        <translation>Diagnose läuft … Schritt %1, aktueller rmse %2</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1: a generic effect of the data row, the part or the dimension says nothing about the next part, so the study (%2) cannot include it; it is reported here and in the residual check, not applied</source>
        <translation>%1: Ein generischer Effekt der Datenzeile, des Teils oder des Maßes sagt nichts über das nächste Teil aus, daher kann die Studie (%2) ihn nicht aufnehmen; er wird hier und in der Residuenprüfung berichtet, aber nicht angewendet</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Nothing to apply. %1.</source>
        <translation>Nichts zu übernehmen. %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Applies %1 only. %2.</source>
        <translation>Übernimmt nur %1. %2.</translation>
    </message>
    <message>
        <location line="+217"/>
        <source>The dataset the %1 diagnosis runs on (studies.diagnosis.%2.dataset)</source>
        <translation>Der Datensatz, auf dem die %1-Diagnose läuft (studies.diagnosis.%2.dataset)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Da&amp;ta:</source>
        <translation>Da&amp;ten:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Choose the %1 diagnosis data</source>
        <translation>Die Daten der %1-Diagnose wählen</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Train &amp;fraction:</source>
        <translation>Trainings&amp;anteil:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The share of the rows (from the start) the model is fitted on; the rest is held out (studies.diagnosis.thermal.train_fraction)</source>
        <translation>Der Anteil der Zeilen (vom Anfang an), an den das Modell angepasst wird; der Rest sind Testdaten (studies.diagnosis.thermal.train_fraction)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change the diagnosis train fraction</source>
        <translation>Den Trainingsanteil der Diagnose ändern</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The log&apos;s column the declared model predicts, whose residual is diagnosed (studies.diagnosis.thermal.target)</source>
        <translation>Die Spalte des Protokolls, die das deklarierte Modell vorhersagt und deren Rest diagnostiziert wird (studies.diagnosis.thermal.target)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tar&amp;get:</source>
        <translation>&amp;Zielgröße:</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Change the diagnosis target</source>
        <translation>Zielgröße der Diagnose ändern</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The declared model&apos;s inputs: the loop looks for what the residual of a model of these inputs still depends on (studies.diagnosis.thermal.inputs)</source>
        <translation>Die Eingänge des deklarierten Modells: die Schleife sucht, wovon der Rest eines Modells dieser Eingänge noch abhängt (studies.diagnosis.thermal.inputs)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Inputs:</source>
        <translation>&amp;Eingänge:</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&amp;Feed:</source>
        <translation>&amp;Vorschub:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The feed of the circular test, for the servo lag&apos;s time constant (studies.diagnosis.kinematic.feed_mm_per_min)</source>
        <translation>Der Vorschub des Kreisformtests, für die Zeitkonstante des Schleppfehlers (studies.diagnosis.kinematic.feed_mm_per_min)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change the diagnosis feed</source>
        <translation>Den Vorschub der Diagnose ändern</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The setup model whose setup data are diagnosed (studies.diagnosis.setup.model)</source>
        <translation>Das Einrichtmodell, dessen Einrichtdaten diagnostiziert werden (studies.diagnosis.setup.model)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Model:</source>
        <translation>&amp;Modell:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Choose the diagnosis setup model</source>
        <translation>Das Einrichtmodell der Diagnose wählen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Tolerance ±:</source>
        <translation>&amp;Toleranz ±:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The symmetric tolerance an effect must matter against (studies.diagnosis.matching.tolerance_mm)</source>
        <translation>Die symmetrische Toleranz, gegen die ein Effekt Gewicht haben muss (studies.diagnosis.matching.tolerance_mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change the diagnosis tolerance</source>
        <translation>Die Toleranz der Diagnose ändern</translation>
    </message>
    <message numerus="yes">
        <location line="+126"/>
        <source>%n column(s)</source>
        <translation>
            <numerusform>%n Spalte</numerusform>
            <numerusform>%n Spalten</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Change the diagnosis inputs</source>
        <translation>Eingänge der Diagnose ändern</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+33"/>
        <location line="+2"/>
        <source>Choose the thermal diagnosis data</source>
        <translation>Daten der Thermik-Diagnose wählen</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>The stored result (computed %1) is out of date: the settings changed since. Not run with these settings yet: press Run (Ctrl+R).</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Einstellungen haben sich seitdem geändert. Mit diesen Einstellungen noch nicht ausgeführt: Ausführen drücken (Strg+R).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the data file changed since. Run (Ctrl+R) on the data as it is now.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Datendatei hat sich seitdem geändert. Ausführen (Strg+R) auf den Daten in ihrem jetzigen Stand.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the data file cannot be read.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) kann nicht geprüft werden: die Datendatei ist nicht lesbar.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>From the saved project (computed %1 with these settings on this data): %2 Run (Ctrl+R) for the plots, the candidate table and the residual check.</source>
        <translation>Aus dem gespeicherten Projekt (berechnet %1 mit diesen Einstellungen auf diesen Daten): %2 Ausführen (Strg+R) für die Diagramme, die Kandidatentabelle und die Residuenprüfung.</translation>
    </message>
    <message>
        <location line="-1034"/>
        <source>rmse %1 → %2 %3</source>
        <translation>rmse %1 → %2 %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, held-out rmse %1 → %2 %3</source>
        <translation>, rmse Testdaten %1 → %2 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, max |e| %1 → %2 %3</source>
        <translation>, max |e| %1 → %2 %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>. No undeclared effect found (%1 candidates tried).</source>
        <translation>. Kein nicht deklarierter Effekt gefunden (%1 Kandidaten getestet).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>. Accepted: %1 (%2 candidates tried).</source>
        <translation>. Übernommen: %1 (%2 Kandidaten getestet).</translation>
    </message>
    <message>
        <location line="+290"/>
        <source>Diagnosis, %1: the settings are invalid; nothing runs until they are corrected (above, Undo, or the project file under studies.diagnosis.%2):
%3</source>
        <translation>Diagnose, %1: die Einstellungen sind ungültig; nichts wird ausgeführt, bis sie korrigiert sind (oben, Rückgängig oder die Projektdatei unter studies.diagnosis.%2):
%3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Diagnosis, %1: choose the data to diagnose above (Data).</source>
        <translation>Diagnose, %1: wählen Sie oben die zu diagnostizierenden Daten (Daten).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diagnosis, %1: the project has no data for it yet. Import it with File › Import data (Ctrl+I).</source>
        <translation>Diagnose, %1: das Projekt hat noch keine Daten dafür. Importieren Sie sie mit Datei › Daten importieren (Strg+I).</translation>
    </message>
    <message>
        <location line="+156"/>
        <source>Cancelled: the rounds done so far.</source>
        <translation>Abgebrochen: die bisherigen Runden.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Residual check: %1.</source>
        <translation>Residuenprüfung: %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Residual chec&amp;k: white</source>
        <translation>Residuen&amp;prüfung: weiß</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Residual chec&amp;k: structure left</source>
        <translation>Residuen&amp;prüfung: Struktur übrig</translation>
    </message>
    <message>
        <location line="+7"/>
        <source> (accepted)</source>
        <translation> (übernommen)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Residual before and after %1</source>
        <translation>Residuen vor und nach %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>form: %1</source>
        <translation>Form: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A generic effect: %1 in %2, for structure no catalogue effect explains</source>
        <translation>Ein generischer Effekt: %1 in %2, für Struktur, die kein Effekt des Katalogs erklärt</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>(Already applied.)</source>
        <translation>(Bereits übernommen.)</translation>
    </message>
</context>
<context>
    <name>metrofit::ErrorBarsView</name>
    <message>
        <location filename="../widgets/diagnose/residualplot.cpp" line="+449"/>
        <source>rmse and largest |error| of the fitted data, rmse of the held-out rows (thermal): the declared model (grey) and the model with the accepted effects (blue)</source>
        <translation>rmse und größter |Fehler| der angepassten Daten, rmse der Testdaten (Thermik): das deklarierte Modell (grau) und das Modell mit den übernommenen Effekten (blau)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Error before / after</source>
        <translation>Fehler vorher / nachher</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Error before / after (%1)</source>
        <translation>Fehler vorher / nachher (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared</source>
        <translation>deklariert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+ effects</source>
        <translation>+ Effekte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>rmse</source>
        <translation>rmse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max |e|</source>
        <translation>max |e|</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>held-out</source>
        <translation>Testdaten</translation>
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
    <name>metrofit::HistogramView</name>
    <message>
        <location filename="../widgets/kinematics/kinematicsviews.cpp" line="+43"/>
        <source>%1 to %2%3
count: %4</source>
        <translation>%1 bis %2%3
Anzahl: %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Distribution of the values with the specification limits LSL/USL, the nominal and the mean.</source>
        <translation>Verteilung der Werte mit den Toleranzgrenzen LSL/USL, dem Nennwert und dem Mittelwert.</translation>
    </message>
</context>
<context>
    <name>metrofit::ImportDialog</name>
    <message>
        <location filename="../widgets/importer/importdialog.cpp" line="+69"/>
        <location line="+15"/>
        <source>comma ( , )</source>
        <translation>Komma ( , )</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>semicolon ( ; )</source>
        <translation>Semikolon ( ; )</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tab</source>
        <translation>Tabulator</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+11"/>
        <location line="+150"/>
        <source>detect</source>
        <translation>erkennen</translation>
    </message>
    <message>
        <location line="-154"/>
        <source>point ( . )</source>
        <translation>Punkt ( . )</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>time in s, strictly increasing</source>
        <translation>Zeit in s, streng steigend</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time in min</source>
        <translation>Zeit in min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time in h</source>
        <translation>Zeit in h</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacement in X in µm (a target)</source>
        <translation>Verlagerung in X in µm (eine Zielgröße)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacement in Y in µm (a target)</source>
        <translation>Verlagerung in Y in µm (eine Zielgröße)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacement in Z in µm (a target)</source>
        <translation>Verlagerung in Z in µm (eine Zielgröße)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ambient temperature in °C</source>
        <translation>Umgebungstemperatur in °C</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spindle speed in 1/min</source>
        <translation>Spindeldrehzahl in 1/min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point id</source>
        <translation>Punktkennung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>surface name</source>
        <translation>Name der Fläche</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>nominal point in mm</source>
        <translation>Sollpunkt in mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>nominal unit normal</source>
        <translation>Soll-Einheitsnormale</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>measured point in mm</source>
        <translation>Messpunkt in mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>commanded coordinate in mm</source>
        <translation>Sollkoordinate in mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>measured coordinate in mm</source>
        <translation>gemessene Koordinate in mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>angle of a radial-only circular test in deg</source>
        <translation>Winkel eines rein radialen Kreisformtests in Grad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>radial deviation in µm (radial-only circular test)</source>
        <translation>radiale Abweichung in µm (rein radialer Kreisformtest)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>radial deviation in mm (radial-only circular test)</source>
        <translation>radiale Abweichung in mm (rein radialer Kreisformtest)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>direction of travel: ccw or cw</source>
        <translation>Fahrtrichtung: ccw (Gegenuhrzeigersinn) oder cw (Uhrzeigersinn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run number</source>
        <translation>Laufnummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nominal radius in mm</source>
        <translation>Nennradius in mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part number</source>
        <translation>Teilenummer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dimension id of the setup model</source>
        <translation>Maßkennung des Einrichtmodells</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nominal value in mm</source>
        <translation>Nennwert in mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured value in mm</source>
        <translation>Messwert in mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lower tolerance in mm</source>
        <translation>untere Toleranz in mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>upper tolerance in mm</source>
        <translation>obere Toleranz in mm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>temperature in °C (an input)</source>
        <translation>Temperatur in °C (eine Eingangsgröße)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>circle</source>
        <translation>Kreis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cylinder</source>
        <translation>Zylinder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cone</source>
        <translation>Kegel</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>Nominals: the %n point(s) of “%1”.</source>
        <translation>
            <numerusform>Sollpunkte: der %n Punkt von „%1“.</numerusform>
            <numerusform>Sollpunkte: die %n Punkte von „%1“.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>radius %1 mm, </source>
        <translation>Radius %1 mm, </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 fitted to %n point(s): %2form %3 mm, rmse %4 mm.</source>
        <translation>
            <numerusform>%1 (an %n Punkt angepasst): %2Form %3 mm, RMSE %4 mm.</numerusform>
            <numerusform>%1 (an %n Punkte angepasst): %2Form %3 mm, RMSE %4 mm.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n stray point(s) left out of the fit.</source>
        <translation>
            <numerusform>%n Ausreißer aus der Anpassung ausgelassen.</numerusform>
            <numerusform>%n Ausreißer aus der Anpassung ausgelassen.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source> The points cover a cap of half angle %1°.</source>
        <translation> Die Punkte decken eine Kugelkappe mit dem halben Öffnungswinkel %1° ab.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> The points cover an arc of %1°.</source>
        <translation> Die Punkte decken einen Bogen von %1° ab.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Badly conditioned: the noise of the points is amplified %1 times in the element.</source>
        <translation>Schlecht konditioniert: das Rauschen der Punkte wird im Element %1-fach verstärkt.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Weakly conditioned: the noise of the points is amplified %1 times in the element.</source>
        <translation>Schwach konditioniert: das Rauschen der Punkte wird im Element %1-fach verstärkt.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Skip &amp;unreadable rows</source>
        <translation>Nicht &amp;lesbare Zeilen überspringen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DMIS tolerance actuals</source>
        <translation>DMIS-Toleranz-Istwerte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cop&amp;y the file into the project (data folder)</source>
        <translation>Datei in das Pro&amp;jekt kopieren (Ordner data)</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+259"/>
        <source>Import data</source>
        <translation>Daten importieren</translation>
    </message>
    <message>
        <location line="-246"/>
        <source>Lines before the column names, skipped whatever they hold (an instrument&apos;s preamble)</source>
        <translation>Zeilen vor den Spaltennamen, unabhängig vom Inhalt übersprungen (Vorspann eines Messgeräts)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What starts a comment line before the column names</source>
        <translation>Womit eine Kommentarzeile vor den Spaltennamen beginnt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Leave out the rows listed under the preview; the project keeps this setting and the readers count the rows they leave out. Off: the first unreadable row is an error.</source>
        <translation>Die unter der Vorschau aufgeführten Zeilen auslassen; das Projekt speichert diese Einstellung, und die Leser zählen die ausgelassenen Zeilen. Aus: Die erste nicht lesbare Zeile ist ein Fehler.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>auto (nearer the nominal: the actual value)</source>
        <translation>automatisch (näher am Nennmaß: der Istwert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deviation (actual − nominal)</source>
        <translation>Abweichung (Ist − Nenn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>actual value</source>
        <translation>Istwert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>plain (actual − nominal)</source>
        <translation>unverändert (Ist − Nenn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>follows the nominal&apos;s sign</source>
        <translation>folgt dem Vorzeichen des Nennmaßes</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Import</source>
        <translation>&amp;Importieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Browse…</source>
        <translation>Du&amp;rchsuchen…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;File:</source>
        <translation>&amp;Datei:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Kind:</source>
        <translation>&amp;Art:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Id:</source>
        <translation>&amp;Kennung:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The measured part (MeasurementResults) of the QIF file whose features become the probe points</source>
        <translation>Das gemessene Teil (MeasurementResults) der QIF-Datei, dessen Merkmale die Antastpunkte werden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Measured &amp;part:</source>
        <translation>Gemessenes &amp;Teil:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The MTConnect log is resampled every this many seconds: each cell holds the last value at or before its time (empty while UNAVAILABLE)</source>
        <translation>Das MTConnect-Protokoll wird in diesem Abstand (Sekunden) neu abgetastet: jede Zelle enthält den letzten Wert zu oder vor ihrer Zeit (leer, solange UNAVAILABLE)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sample &amp;interval:</source>
        <translation>Abtastinter&amp;vall:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>How the file is read</source>
        <translation>Wie die Datei gelesen wird</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Delimiter:</source>
        <translation>&amp;Trennzeichen:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Decimal &amp;mark:</source>
        <translation>Dezimal&amp;zeichen:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Comment prefix:</source>
        <translation>&amp;Kommentarzeichen:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Lines before the header:</source>
        <translation>Zeilen &amp;vor der Kopfzeile:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Found:</source>
        <translation>Gefunden:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TA &amp;value is:</source>
        <translation>TA-&amp;Wert ist:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TA si&amp;gn:</source>
        <translation>TA-Vor&amp;zeichen:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Column in the file</source>
        <translation>Spalte in der Datei</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>First value</source>
        <translation>Erster Wert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Read as</source>
        <translation>Lesen als</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Columns</source>
        <translation>Spalten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Give a column the name the readers look for (time_s, disp_z_um, qx, x_cmd_mm, …); empty: the name in the file. The project stores this mapping, not a converted copy.</source>
        <translation>Geben Sie einer Spalte den Namen, den die Leser erwarten (time_s, disp_z_um, qx, x_cmd_mm, …); leer: der Name in der Datei. Das Projekt speichert diese Zuordnung, keine umgewandelte Kopie.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preview (first %1 rows)</source>
        <translation>Vorschau (erste %1 Zeilen)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+613"/>
        <source>Rows that cannot be read:</source>
        <translation>Nicht lesbare Zeilen:</translation>
    </message>
    <message>
        <location line="-549"/>
        <source>Copy the file to the project&apos;s data folder as &lt;id&gt;.&lt;extension&gt; and refer to the copy; the import never overwrites a file there</source>
        <translation>Die Datei als &lt;id&gt;.&lt;Endung&gt; in den Ordner data des Projekts kopieren und auf die Kopie verweisen; der Import überschreibt dort nie eine Datei</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the project first: the copy goes into the project&apos;s folder</source>
        <translation>Zuerst das Projekt speichern: Die Kopie kommt in den Ordner des Projekts</translation>
    </message>
    <message>
        <location line="+61"/>
        <location line="+6"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data files (*.csv *.txt *.tsv *.json *.dmi *.dms *.dmis *.xml *.qif *.QIF *.dfq *.DFQ *.stl *.STL)</source>
        <translation>Datendateien (*.csv *.txt *.tsv *.json *.dmi *.dms *.dmis *.xml *.qif *.QIF *.dfq *.DFQ *.stl *.STL)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: cannot read the file (%2)</source>
        <translation>%1: die Datei kann nicht gelesen werden (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the file is larger than 256 MiB</source>
        <translation>%1: die Datei ist größer als 256 MiB</translation>
    </message>
    <message numerus="yes">
        <location line="+187"/>
        <source>Read the %n selected files as one DMIS &amp;series (one dataset, one file per workpiece)</source>
        <translation>
            <numerusform>Die %n ausgewählte Datei als eine DMIS-&amp;Serie lesen (ein Datensatz, eine Datei je Werkstück)</numerusform>
            <numerusform>Die %n ausgewählten Dateien als eine DMIS-&amp;Serie lesen (ein Datensatz, eine Datei je Werkstück)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Also: %1</source>
        <translation>Außerdem: %1</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>as in the file</source>
        <translation>wie in der Datei</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Line</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>DMIS output: add a setup model to the project to preview the deviations read with these settings.</source>
        <translation>DMIS-Ausgabe: Fügen Sie dem Projekt ein Einrichtmodell hinzu, um die mit diesen Einstellungen gelesenen Abweichungen in der Vorschau zu sehen.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Dimension</source>
        <translation>Maß</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deviation (mm)</source>
        <translation>Abweichung (mm)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>DMIS output read against the setup model “%1”.</source>
        <translation>DMIS-Ausgabe, gelesen mit dem Einrichtmodell „%1“.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DMIS series of %1 files read against the setup model “%2”: the mean deviation over the workpieces.</source>
        <translation>DMIS-Serie aus %1 Dateien, gelesen gegen das Einrichtmodell „%2“: die mittlere Abweichung über die Werkstücke.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>DMIS output; read against the setup model “%1”: %2</source>
        <translation>DMIS-Ausgabe; gelesen mit dem Einrichtmodell „%1“: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>MTConnect log resampled every %1 s (zero-order hold: the last value at or before each time): %2 rows, %3 sample columns; %4 data items are not columns (events, conditions, no numbers).</source>
        <translation>MTConnect-Protokoll, alle %1 s neu abgetastet (Halteglied nullter Ordnung: der letzte Wert zu oder vor jeder Zeit): %2 Zeilen, %3 Messwertspalten; %4 Datenelemente sind keine Spalten (Ereignisse, Zustände, keine Zahlen).</translation>
    </message>
    <message numerus="yes">
        <location line="+39"/>
        <source>%n feature row(s)</source>
        <translation>
            <numerusform>%n Merkmalszeile</numerusform>
            <numerusform>%n Merkmalszeilen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n row(s)</source>
        <translation>
            <numerusform>%n Zeile</numerusform>
            <numerusform>%n Zeilen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: read as %2, %3.</source>
        <translation>%1: gelesen als %2, %3.</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Choose a file to import.</source>
        <translation>Wählen Sie eine Datei zum Importieren.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Not a CSV file: read as %1 (no delimiter, decimal mark or column mapping).</source>
        <translation>Keine CSV-Datei: gelesen als %1 (ohne Trennzeichen, Dezimalzeichen und Spaltenzuordnung).</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>detect (%1)</source>
        <translation>erkennen (%1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Rows that cannot be read (%1): tick “Skip unreadable rows” to import without them.</source>
        <translation>Nicht lesbare Zeilen (%1): „Nicht lesbare Zeilen überspringen“ ankreuzen, um ohne sie zu importieren.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Rows that cannot be read (%1), left out:</source>
        <translation>Nicht lesbare Zeilen (%1), ausgelassen:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (detected)</source>
        <translation>%1 (erkannt)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>delimiter %1 · decimal mark %2 · header in line %3 (%4 columns) · comment lines: %5 · data rows: %6</source>
        <translation>Trennzeichen %1 · Dezimalzeichen %2 · Kopfzeile in Zeile %3 (%4 Spalten) · Kommentarzeilen: %5 · Datenzeilen: %6</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Nominals: the closest points of the CAD part “%1”; the matching moves the points onto it at each posture (closed form or minimum zone).</source>
        <translation>Sollpunkte: die nächsten Punkte des CAD-Teils „%1“; das Einpassen projiziert die Punkte bei jeder Lage neu darauf (geschlossene Lösung oder Minimumzone).</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1: already exists; an embedded copy never overwrites a file (choose another id)</source>
        <translation>%1: existiert bereits; eine eingebettete Kopie überschreibt nie eine Datei (andere Kennung wählen)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ready to import as %1 “%2”.</source>
        <translation>Bereit zum Import als %1 „%2“.</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>The %n file(s) are one DMIS series: one workpiece per file.</source>
        <translation>
            <numerusform>Die %n Datei ist eine DMIS-Serie: ein Werkstück je Datei.</numerusform>
            <numerusform>Die %n Dateien sind eine DMIS-Serie: ein Werkstück je Datei.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n unreadable row(s) will be left out.</source>
        <translation>
            <numerusform>%n nicht lesbare Zeile wird ausgelassen.</numerusform>
            <numerusform>%n nicht lesbare Zeilen werden ausgelassen.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The file is copied to %1.</source>
        <translation>Die Datei wird nach %1 kopiert.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Nominals of the measured points</source>
        <translation>Sollpunkte der Messpunkte</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a fitted element</source>
        <translation>einem angepassten Element</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a second measurement of the part</source>
        <translation>einer zweiten Messung des Teils</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a CAD part</source>
        <translation>einem CAD-Teil</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no normals (positions only)</source>
        <translation>keine Normalen (nur Positionen)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>free (fitted)</source>
        <translation>frei (angepasst)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A calibrated or drawing radius the element keeps; free: fitted</source>
        <translation>Ein kalibrierter oder Zeichnungsradius, den das Element behält; frei: angepasst</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>least squares</source>
        <translation>kleinste Quadrate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>minimum zone</source>
        <translation>Minimumzone</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Bore or hole (material outside)</source>
        <translation>&amp;Bohrung (Material außen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The normals point out of the material: into a bore, out of a shaft or ball</source>
        <translation>Die Normalen zeigen aus dem Material: in eine Bohrung hinein, aus einer Welle oder Kugel heraus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Leave stray points out of the fit</source>
        <translation>Ausreißer aus der Anpassung auslassen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Import the part&apos;s STL file first</source>
        <translation>Zuerst die STL-Datei des Teils importieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>by id</source>
        <translation>nach ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>by order</source>
        <translation>nach Reihenfolge</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Import the first measurement of the part first</source>
        <translation>Zuerst die erste Messung des Teils importieren</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Measurement:</source>
        <translation>&amp;Messung:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;From:</source>
        <translation>&amp;Aus:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Radius:</source>
        <translation>&amp;Radius:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Element:</source>
        <translation>&amp;Element:</translation>
    </message>
</context>
<context>
    <name>metrofit::KinematicPlots</name>
    <message>
        <location filename="../widgets/kinematics/kinematicplots.cpp" line="+360"/>
        <source>0 µm</source>
        <translation>0 µm</translation>
    </message>
    <message>
        <location line="-98"/>
        <source>measured, CCW loop</source>
        <translation>gemessen, Umlauf gegen den Uhrzeigersinn</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured, CW loop</source>
        <translation>gemessen, Umlauf im Uhrzeigersinn</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>expected after compensation</source>
        <translation>erwartet nach Kompensation</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nominal R %1 mm</source>
        <translation>Nenn-R %1 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nominal circle (radius not in the file, drawn as %1 mm)</source>
        <translation>Nennkreis (Radius nicht in der Datei, gezeichnet mit %1 mm)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>plotted radius = R + k × radial deviation, k = %1; rings every %2 µm</source>
        <translation>dargestellter Radius = R + k × radiale Abweichung, k = %1; Ringe alle %2 µm</translation>
    </message>
    <message>
        <location line="+197"/>
        <source>X (mm)</source>
        <translation>X (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y (mm)</source>
        <translation>Y (mm)</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>nominal circle</source>
        <translation>Nennkreis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>measured CCW</source>
        <translation>gemessen, Gegenuhrzeigersinn</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>measured CW</source>
        <translation>gemessen, Uhrzeigersinn</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>compensated references</source>
        <translation>kompensierte Sollwerte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>expected after</source>
        <translation>erwartet nachher</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>deviations from the nominal point × %1</source>
        <translation>Abweichungen vom Nennpunkt × %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>one point beyond the control limits</source>
        <translation>ein Punkt außerhalb der Eingriffsgrenzen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nine in a row on one side of the centre line</source>
        <translation>neun in Folge auf einer Seite der Mittellinie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>six in a row steadily increasing or decreasing</source>
        <translation>sechs in Folge stetig steigend oder fallend</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fourteen in a row alternating up and down</source>
        <translation>vierzehn in Folge abwechselnd auf und ab</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>two of three beyond 2 σ on the same side</source>
        <translation>zwei von drei jenseits 2 σ auf derselben Seite</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>four of five beyond 1 σ on the same side</source>
        <translation>vier von fünf jenseits 1 σ auf derselben Seite</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fifteen in a row within 1 σ</source>
        <translation>fünfzehn in Folge innerhalb 1 σ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>eight in a row beyond 1 σ on either side</source>
        <translation>acht in Folge jenseits 1 σ auf beiden Seiten</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Nelson %1: %2</source>
        <translation>Nelson %1: %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>X-bar</source>
        <translation>X-quer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MR</source>
        <translation>MR</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %2 at %3</source>
        <translation>%1 %2 bei %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none broken</source>
        <translation>keine verletzt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (limits from subgroups 1–%1)</source>
        <translation> (Grenzen aus den Stichproben 1–%1)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>X chart (individual values)</source>
        <translation>X-Karte (Einzelwerte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MR chart (moving range of 2)</source>
        <translation>MR-Karte (gleitende Spannweite aus 2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X-bar chart (subgroups of %1)</source>
        <translation>x̄-Karte (Untergruppen zu %1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R chart (subgroups of %1)</source>
        <translation>R-Karte (Untergruppen zu %1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, limits from subgroups 1–%1</source>
        <translation>, Grenzen aus den Stichproben 1–%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>moving range</source>
        <translation>gleitende Spannweite</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>subgroup</source>
        <translation>Untergruppe</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>subgroup mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>subgroup range</source>
        <translation>Spannweite</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>UCL</source>
        <comment>upper control limit</comment>
        <translation>UCL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CL</source>
        <comment>centre line</comment>
        <translation>CL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LCL</source>
        <comment>lower control limit</comment>
        <translation>LCL</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>phase I</source>
        <translation>Phase I</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>phase II</source>
        <translation>Phase II</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>Histogram</source>
        <translation>Histogramm</translation>
    </message>
    <message>
        <location line="-120"/>
        <location line="+127"/>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>LSL</source>
        <comment>lower specification limit</comment>
        <translation>LSL</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>USL</source>
        <comment>upper specification limit</comment>
        <translation>USL</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nominal</source>
        <translation>Nennwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean</source>
        <translation>Mittelwert</translation>
    </message>
</context>
<context>
    <name>metrofit::KinematicsPage</name>
    <message>
        <location filename="../app/gui/kinematicspage.cpp" line="+179"/>
        <source>&amp;Identify</source>
        <translation>&amp;Identifizieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Compensate</source>
        <translation>&amp;Kompensieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;G-code…</source>
        <translation>&amp;G-Code exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;STEP-NC…</source>
        <translation>&amp;STEP-NC exportieren…</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Identify the actuator origin and orientation errors of the circular test (Levenberg-Marquardt, standard errors from the residuals) (F5)</source>
        <translation>Ursprungs- und Orientierungsfehler der Antriebe aus dem Kreisformtest identifizieren (Levenberg-Marquardt, Standardfehler aus den Residuen) (F5)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Compensated references for the nominal circle (Eq. 15 with the identified errors), and what they give (Ctrl+K)</source>
        <translation>Kompensierte Sollwerte für den Nennkreis (Gl. 15 mit den identifizierten Fehlern) und ihre Wirkung (Strg+K)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the compensated references as G-code (G01 blocks)</source>
        <translation>Die kompensierten Sollwerte als G-Code schreiben (G01-Sätze)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the compensated references as a STEP-NC (ISO 10303-21) file</source>
        <translation>Die kompensierten Sollwerte als STEP-NC-Datei (ISO 10303-21) schreiben</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+127"/>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location line="-127"/>
        <source>identified</source>
        <translation>identifiziert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>std. error</source>
        <translation>Std.-Fehler</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>simulated</source>
        <translation>simuliert</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>max radial deviation</source>
        <translation>max. radiale Abweichung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Identified errors&lt;/b&gt; (origin in µm, angles in deg)</source>
        <translation>&lt;b&gt;Identifizierte Fehler&lt;/b&gt; (Ursprung in µm, Winkel in Grad)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Effects added with Apply on the Diagnosis page: the identification, the compensated references and their exports include them. Undo the Apply to use the declared model again.</source>
        <translation>Mit „Ins Modell übernehmen“ auf der Seite „Diagnose“ hinzugefügte Effekte: Die Identifikation, die kompensierten Sollwerte und deren Exporte berücksichtigen sie. Machen Sie die Übernahme rückgängig, um wieder das deklarierte Modell zu verwenden.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;b&gt;Compensation&lt;/b&gt; of the nominal circle</source>
        <translation>&lt;b&gt;Kompensation&lt;/b&gt; des Nennkreises</translation>
    </message>
    <message>
        <location line="+207"/>
        <source>cause</source>
        <translation>Ursache</translation>
    </message>
    <message>
        <location line="-189"/>
        <source>&amp;Path</source>
        <translation>Bah&amp;n</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Se&amp;ries:</source>
        <translation>&amp;Reihe:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The measured series charted (a feature series or a CMM report, one value per part; studies.kinematics.spc.dataset)</source>
        <translation>Die dargestellte Messreihe (eine Merkmalsreihe oder ein KMG-Protokoll, ein Wert je Teil; studies.kinematics.spc.dataset)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>C&amp;haracteristic:</source>
        <translation>&amp;Merkmal:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The column of the series charted (studies.kinematics.spc.column)</source>
        <translation>Die dargestellte Spalte der Reihe (studies.kinematics.spc.column)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>S&amp;ubgroup:</source>
        <translation>&amp;Untergruppe:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Consecutive parts per subgroup of the X-bar/R chart (studies.kinematics.spc.subgroup)</source>
        <translation>Aufeinanderfolgende Teile je Untergruppe der X-quer/R-Karte (studies.kinematics.spc.subgroup)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;LSL:</source>
        <translation>UG&amp;W:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lower specification limit, in the series&apos; unit (studies.kinematics.spc.lsl)</source>
        <translation>Unterer Grenzwert (Spezifikation), in der Einheit der Reihe (studies.kinematics.spc.lsl)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Upper specification limit, in the series&apos; unit (studies.kinematics.spc.usl)</source>
        <translation>Oberer Grenzwert (Spezifikation), in der Einheit der Reihe (studies.kinematics.spc.usl)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Nominal:</source>
        <translation>&amp;Nennwert:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The desired value, in the series&apos; unit (studies.kinematics.spc.nominal)</source>
        <translation>Der Sollwert, in der Einheit der Reihe (studies.kinematics.spc.nominal)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Choose the SPC characteristic</source>
        <translation>SPC-Merkmal wählen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Change the SPC subgroup size</source>
        <translation>SPC-Untergruppengröße ändern</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export Q-DAS &amp;DFQ…</source>
        <translation>Q-DAS-&amp;DFQ exportieren…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>S&amp;PC</source>
        <translation>S&amp;PC</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>from SPC</source>
        <translation>aus SPC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>from circular test</source>
        <translation>aus Kreisformtest</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>u axis angle a (°)</source>
        <translation>Winkel der u-Achse a (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>v axis angle b (°)</source>
        <translation>Winkel der v-Achse b (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>squareness b − a (°)</source>
        <translation>Rechtwinkligkeit b − a (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>± std. error (°)</source>
        <translation>± Standardfehler (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMS (µm)</source>
        <translation>RMS (µm)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Choose the edge along X</source>
        <translation>Kante entlang X wählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the edge along Y</source>
        <translation>Kante entlang Y wählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the XY circular test</source>
        <translation>Kreisformtest XY wählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the YZ circular test</source>
        <translation>Kreisformtest YZ wählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the ZX circular test</source>
        <translation>Kreisformtest ZX wählen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Edge along &amp;X:</source>
        <translation>Kante entlang &amp;X:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Edge along &amp;Y:</source>
        <translation>Kante entlang &amp;Y:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>XY circular &amp;test:</source>
        <translation>K&amp;reisformtest XY:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y&amp;Z circular test:</source>
        <translation>Kreisformtest Y&amp;Z:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ZX circ&amp;ular test:</source>
        <translation>Kreisfor&amp;mtest ZX:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The edge machined along X and measured (feature series, CSV position_mm,deviation_mm)</source>
        <translation>Die entlang X bearbeitete und gemessene Kante (Merkmalsreihe, CSV position_mm,deviation_mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The edge machined along Y and measured (feature series, CSV position_mm,deviation_mm)</source>
        <translation>Die entlang Y bearbeitete und gemessene Kante (Merkmalsreihe, CSV position_mm,deviation_mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular test in the XY plane (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)</source>
        <translation>Kreisformtest in der XY-Ebene (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular test in the YZ plane (CSV y_cmd_mm,z_cmd_mm,y_meas_mm,z_meas_mm)</source>
        <translation>Kreisformtest in der YZ-Ebene (CSV y_cmd_mm,z_cmd_mm,y_meas_mm,z_meas_mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular test in the ZX plane (CSV z_cmd_mm,x_cmd_mm,z_meas_mm,x_meas_mm)</source>
        <translation>Kreisformtest in der ZX-Ebene (CSV z_cmd_mm,x_cmd_mm,z_meas_mm,x_meas_mm)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Save &amp;DFQ…</source>
        <translation>DF&amp;Q speichern…</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>&amp;Actuators</source>
        <translation>&amp;Antriebe</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The radial deviation of both runs fitted to the signature of each cause, after the centre and radius of each run (as metrofit-cli kinematic identify writes it under &quot;causes&quot;). Share: the part of the radial deviation&apos;s variance the cause explains. Grey: within the noise (at most three standard errors).</source>
        <translation>Die radiale Abweichung beider Läufe, angepasst an die Signatur jeder Ursache, nach Mittelpunkt und Radius jedes Laufs (wie metrofit-cli kinematic identify sie unter &quot;causes&quot; schreibt). Anteil: der Teil der Varianz der radialen Abweichung, den die Ursache erklärt. Grau: im Rauschen (höchstens drei Standardfehler).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>value (µm)</source>
        <translation>Wert (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>± std. error (µm)</source>
        <translation>± Standardfehler (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>share (%)</source>
        <translation>Anteil (%)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Ballbar</source>
        <translation>&amp;Ballbar</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>C&amp;ircular test:</source>
        <translation>Kreisform&amp;test:</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Compensate</source>
        <translation>Kompensieren</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+100"/>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <location line="-90"/>
        <source>%1 (not a dataset id)</source>
        <translation>%1 (keine Datensatz-ID)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (not in the project)</source>
        <translation>%1 (nicht im Projekt)</translation>
    </message>
    <message>
        <location line="+146"/>
        <source>Remove the SPC series</source>
        <translation>SPC-Reihe entfernen</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>“%1” has no column of numbers to chart.</source>
        <translation>„%1“ hat keine Zahlenspalte zum Darstellen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+2"/>
        <location line="+2"/>
        <source>Choose the SPC series</source>
        <translation>SPC-Reihe wählen</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Not a number: %1</source>
        <translation>Keine Zahl: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Give both specification limits (LSL and USL), or neither; nothing is written until then.</source>
        <translation>Geben Sie beide Grenzwerte (UGW und OGW) an oder keinen; bis dahin wird nichts geschrieben.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The lower specification limit must be below the upper one.</source>
        <translation>Der untere Grenzwert muss unter dem oberen liegen.</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+2"/>
        <source>Change the SPC limits</source>
        <translation>SPC-Grenzwerte ändern</translation>
    </message>
    <message>
        <location line="+78"/>
        <source>This project has no circular test. Add a dataset of kind &quot;circular_test&quot; (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm, one loop CCW then one CW), e.g. made by metrofit-cli simulate circular.</source>
        <translation>Dieses Projekt enthält keinen Kreisformtest. Fügen Sie einen Datensatz der Art „circular_test“ hinzu (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm, ein Umlauf gegen und einer im Uhrzeigersinn), z. B. erzeugt mit metrofit-cli simulate circular.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No circular test in this project: only the SPC tab is available. %1</source>
        <translation>Kein Kreisformtest in diesem Projekt: nur der Reiter SPC ist verfügbar. %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import a circular test (Ctrl+I) for the path, actuators and ballbar tabs.</source>
        <translation>Importieren Sie einen Kreisformtest (Strg+I) für die Reiter Bahn, Antriebe und Ballbar.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Cannot identify this circular test:
%1</source>
        <translation>Dieser Kreisformtest kann nicht identifiziert werden:
%1</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1: G %2 µm, F %3 … %4 µm</source>
        <translation>%1: G %2 µm, F %3 … %4 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CCW</source>
        <translation>GUZ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CW</source>
        <translation>UZ</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>H %1 µm</source>
        <translation>H %1 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ISO 230-4: %1</source>
        <translation>ISO 230-4: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%1 points, nominal circle R %2 mm about (%3, %4) mm; %n loop(s).</source>
        <translation>
            <numerusform>%1 Punkte, Nennkreis R %2 mm um (%3; %4) mm; %n Umlauf.</numerusform>
            <numerusform>%1 Punkte, Nennkreis R %2 mm um (%3; %4) mm; %n Umläufe.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Effects applied on the Diagnosis page belong to the circular test %1 (the one the diagnosis ran on); this test uses the declared model.</source>
        <translation>Die auf der Seite „Diagnose“ übernommenen Effekte gehören zum Kreisformtest %1 (auf dem die Diagnose lief); dieser Test verwendet das deklarierte Modell.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Includes applied effects: %1</source>
        <translation>Enthält übernommene Effekte: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+136"/>
        <source>origin x (µm)</source>
        <translation>Ursprung x (µm)</translation>
    </message>
    <message>
        <location line="-134"/>
        <source>Where the tool is at command 0 (Oyr of Eq. 9), x</source>
        <translation>Wo das Werkzeug beim Sollwert 0 steht (Oyr aus Gl. 9), x</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+134"/>
        <source>origin y (µm)</source>
        <translation>Ursprung y (µm)</translation>
    </message>
    <message>
        <location line="-132"/>
        <source>Where the tool is at command 0 (Oyr of Eq. 9), y</source>
        <translation>Wo das Werkzeug beim Sollwert 0 steht (Oyr aus Gl. 9), y</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+132"/>
        <source>X axis angle a (deg)</source>
        <translation>Winkel der X-Achse a (Grad)</translation>
    </message>
    <message>
        <location line="-130"/>
        <source>The X actuator moves along (cos a, sin a); counter-clockwise positive</source>
        <translation>Der X-Antrieb bewegt sich entlang (cos a, sin a); gegen den Uhrzeigersinn positiv</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+130"/>
        <source>Y axis angle b (deg)</source>
        <translation>Winkel der Y-Achse b (Grad)</translation>
    </message>
    <message>
        <location line="-128"/>
        <source>The Y actuator moves along (-sin b, cos b); counter-clockwise positive</source>
        <translation>Der Y-Antrieb bewegt sich entlang (-sin b, cos b); gegen den Uhrzeigersinn positiv</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+128"/>
        <source>squareness b − a (deg)</source>
        <translation>Rechtwinkligkeit b − a (Grad)</translation>
    </message>
    <message>
        <location line="-126"/>
        <source>The angle between the axes is 90° + (b − a)</source>
        <translation>Der Winkel zwischen den Achsen beträgt 90° + (b − a)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMS residual (µm)</source>
        <translation>RMS-Residuum (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Root mean square of the residual distances after identification, with the applied effects</source>
        <translation>Quadratischer Mittelwert der Restabstände nach der Identifikation, mit den übernommenen Effekten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Root mean square of the residual distances after identification</source>
        <translation>Quadratischer Mittelwert der Restabstände nach der Identifikation</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>iterations</source>
        <translation>Iterationen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS, declared model only (µm)</source>
        <translation>RMS, nur deklariertes Modell (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The residual of the declared model (origin and axis angles, no applied effects)</source>
        <translation>Das Residuum des deklarierten Modells (Ursprung und Achswinkel, ohne übernommene Effekte)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Path (XY)</source>
        <translation>Bahn (XY)</translation>
    </message>
    <message>
        <location line="-136"/>
        <location line="+155"/>
        <source>No SPC series is chosen: choose the measured series and its characteristic above (a feature series or a CMM report, imported with File › Import data, Ctrl+I).</source>
        <translation>Keine SPC-Reihe gewählt: wählen Sie oben die Messreihe und ihr Merkmal (eine Merkmalsreihe oder ein KMG-Protokoll, importiert mit Datei › Daten importieren, Strg+I).</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&lt;b&gt;Ballbar breakdown&lt;/b&gt;: not available (%1)</source>
        <translation>&lt;b&gt;Ballbar-Aufschlüsselung&lt;/b&gt;: nicht verfügbar (%1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&lt;b&gt;Ballbar breakdown&lt;/b&gt; (ranked by share)</source>
        <translation>&lt;b&gt;Ballbar-Aufschlüsselung&lt;/b&gt; (nach Anteil geordnet)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;Ballbar breakdown&lt;/b&gt; (ranked by share; one direction: no reversal causes)</source>
        <translation>&lt;b&gt;Ballbar-Aufschlüsselung&lt;/b&gt; (nach Anteil geordnet; eine Richtung: keine Umkehrursachen)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Within the noise: |%1 µm| is at most three standard errors (%2 µm)</source>
        <translation>Im Rauschen: |%1 µm| ist höchstens drei Standardfehler (%2 µm)</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>&lt;b&gt;From SPC to compensation&lt;/b&gt;: choose the edges machined along X and along Y above (feature series, CSV position_mm,deviation_mm in mm, e.g. made by metrofit-cli simulate edge).</source>
        <translation>&lt;b&gt;Von SPC zur Kompensation&lt;/b&gt;: Wählen Sie oben die entlang X und entlang Y bearbeiteten Kanten (Merkmalsreihen, CSV position_mm,deviation_mm in mm, z. B. erzeugt mit metrofit-cli simulate edge).</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>&lt;b&gt;Three axes&lt;/b&gt;: choose the circular tests in the XY, YZ and ZX planes above (made e.g. by metrofit-cli simulate circular --plane yz).</source>
        <translation>&lt;b&gt;Drei Achsen&lt;/b&gt;: Wählen Sie oben die Kreisformtests in den Ebenen XY, YZ und ZX (z. B. erzeugt mit metrofit-cli simulate circular --plane yz).</translation>
    </message>
    <message>
        <location line="-268"/>
        <location line="+110"/>
        <source>Radial deviation (polar, magnified)</source>
        <translation>Radiale Abweichung (polar, vergrößert)</translation>
    </message>
    <message>
        <location line="-693"/>
        <source>USL:</source>
        <translation>OGW:</translation>
    </message>
    <message>
        <location line="+502"/>
        <source>The kinematics study&apos;s settings are invalid; nothing is run until they are corrected (Undo, or the project file):
%1</source>
        <translation>Die Einstellungen der Kinematik-Studie sind ungültig; nichts wird ausgeführt, bis sie korrigiert sind (Rückgängig oder die Projektdatei):
%1</translation>
    </message>
    <message>
        <location line="+194"/>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Write the feature series with its limits as a Q-DAS DFQ file (the K-field file SPC packages import)</source>
        <translation>Die Merkmalsreihe mit ihren Grenzen als Q-DAS-DFQ-Datei schreiben (die K-Feld-Datei, die SPC-Programme importieren)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The kinematics study names no SPC series to export</source>
        <translation>Die Kinematikstudie nennt keine SPC-Reihe zum Exportieren</translation>
    </message>
    <message>
        <location line="-150"/>
        <location line="+155"/>
        <source>Cannot chart the SPC series:
%1</source>
        <translation>Die SPC-Reihe kann nicht dargestellt werden:
%1</translation>
    </message>
    <message numerus="yes">
        <location line="+57"/>
        <source>compensation applied: %n of 4 line parameters beyond ± k standard errors (k = %1), residuals in control</source>
        <translation>
            <numerusform>Kompensation angewendet: %n von 4 Geradenparametern außerhalb ± k Standardfehler (k = %1), Residuen beherrscht</numerusform>
            <numerusform>Kompensation angewendet: %n von 4 Geradenparametern außerhalb ± k Standardfehler (k = %1), Residuen beherrscht</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not compensated: the residuals about a regression line are out of control (special causes first)</source>
        <translation>nicht kompensiert: die Residuen um eine Regressionsgerade sind außer Kontrolle (zuerst die besonderen Ursachen beseitigen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not compensated: no slope or intercept beyond ± k standard errors (random scatter)</source>
        <translation>nicht kompensiert: keine Steigung und kein Achsenabschnitt außerhalb ± k Standardfehler (zufällige Streuung)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;b&gt;From SPC to compensation&lt;/b&gt; (IEEE Access, kinematic compensation algorithm): the offset angle of the regression line of the edge along X is the X actuator&apos;s angle a, minus that of the edge along Y is b (Eq. 9), the intercepts give the origin; %1.</source>
        <translation>&lt;b&gt;Von SPC zur Kompensation&lt;/b&gt; (IEEE Access, Algorithmus zur kinematischen Kompensation): Der Versatzwinkel der Regressionsgeraden der Kante entlang X ist der Winkel a des X-Antriebs, der negative Versatzwinkel der Kante entlang Y ist b (Gl. 9), die Achsenabschnitte ergeben den Ursprung; %1.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>offset angle, edge along X (°)</source>
        <translation>Versatzwinkel, Kante entlang X (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+4"/>
        <source>atan(slope) of the deviation against the position (Fig. 10); ± %1°</source>
        <translation>atan(Steigung) der Abweichung über der Position (Abb. 10); ± %1°</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>offset angle, edge along Y (°)</source>
        <translation>Versatzwinkel, Kante entlang Y (°)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>largest correction (µm)</source>
        <translation>größte Korrektur (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest |reference − nominal point| of the Eq. 15 references for the nominal circle</source>
        <translation>Größtes |Sollwert − Nennpunkt| der Sollwerte nach Gl. 15 für den Nennkreis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>circular test model: before → after (µm)</source>
        <translation>Modell des Kreisformtests: vorher → nachher (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The machine identified from the circular test (an independent estimate) on the nominal circle and on the references derived from SPC: largest distance from the nominal points</source>
        <translation>Die aus dem Kreisformtest identifizierte Maschine (eine unabhängige Schätzung) auf dem Nennkreis und auf den aus SPC abgeleiteten Sollwerten: größter Abstand von den Nennpunkten</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&lt;b&gt;From SPC to compensation&lt;/b&gt;: cannot derive the actuator errors:&lt;br&gt;%1</source>
        <translation>&lt;b&gt;Von SPC zur Kompensation&lt;/b&gt;: Die Antriebsfehler können nicht abgeleitet werden:&lt;br&gt;%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&lt;b&gt;Three axes&lt;/b&gt; from circular tests in XY, YZ and ZX: origin (%1, %2, %3) µm ± %4 µm, RMS residual %5 µm, %6 points.</source>
        <translation>&lt;b&gt;Drei Achsen&lt;/b&gt; aus Kreisformtests in XY, YZ und ZX: Ursprung (%1; %2; %3) µm ± %4 µm, RMS-Residuum %5 µm, %6 Punkte.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>In the plane (u, v) the u actuator moves along (cos a, sin a), the v actuator along (−sin b, cos b); the angle between them is 90° + (b − a)</source>
        <translation>In der Ebene (u, v) bewegt sich der u-Antrieb entlang (cos a, sin a), der v-Antrieb entlang (−sin b, cos b); der Winkel zwischen ihnen ist 90° + (b − a)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&lt;b&gt;Three axes&lt;/b&gt;: cannot identify:&lt;br&gt;%1</source>
        <translation>&lt;b&gt;Drei Achsen&lt;/b&gt;: Identifikation nicht möglich:&lt;br&gt;%1</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>The stored result (computed %1) is out of date: the kinematics settings changed since. Compensate (Ctrl+K) to compute it with these settings.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Kinematik-Einstellungen haben sich seitdem geändert. Kompensieren (Strg+K), um es mit diesen Einstellungen zu berechnen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the circular test&apos;s file changed since. Compensate (Ctrl+K) to compute it on the test as it is now.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Datei des Kreisformtests hat sich seitdem geändert. Kompensieren (Strg+K), um es für den Test in seinem jetzigen Stand zu berechnen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the circular test&apos;s file cannot be read.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) kann nicht geprüft werden: die Datei des Kreisformtests ist nicht lesbar.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>From the saved project, computed %1 with these settings on this test: identified origin (%2, %3) µm, X axis angle a %4°, Y axis angle b %5°, squareness b − a %6°, RMS residual %7 µm. Compensation: max radial deviation %8 µm measured, %9 µm expected after (RMS %10 µm), largest correction %11 µm.</source>
        <translation>Aus dem gespeicherten Projekt, berechnet %1 mit diesen Einstellungen auf diesem Test: identifizierter Ursprung (%2; %3) µm, Winkel der X-Achse a %4°, Winkel der Y-Achse b %5°, Rechtwinkligkeit b − a %6°, RMS-Residuum %7 µm. Kompensation: größte radiale Abweichung %8 µm gemessen, %9 µm danach erwartet (RMS %10 µm), größte Korrektur %11 µm.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Simulated machine after: %1 µm.</source>
        <translation>Simulierte Maschine danach: %1 µm.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compensate (Ctrl+K) to see the compensated path.</source>
        <translation>Kompensieren (Strg+K), um die kompensierte Bahn zu sehen.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>measured (before)</source>
        <translation>gemessen (vorher)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest |radial deviation| of the measured path from the nominal circle</source>
        <translation>Größte |radiale Abweichung| der gemessenen Bahn vom Nennkreis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identified model, after</source>
        <translation>identifiziertes Modell, nachher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The compensated references run through the identified model (Eq. 9): on the circle up to rounding</source>
        <translation>Die kompensierten Sollwerte durch das identifizierte Modell (Gl. 9) geführt: bis auf Rundung auf dem Kreis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>expected after (measured residual)</source>
        <translation>erwartet nachher (gemessenes Residuum)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The measured path moved by what the references change: the residual the model does not explain (noise, unmodelled effects) stays</source>
        <translation>Die gemessene Bahn, verschoben um die Änderung der Sollwerte: das vom Modell nicht erklärte Residuum (Rauschen, nicht modellierte Effekte) bleibt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>expected after, RMS distance</source>
        <translation>erwartet nachher, RMS-Abstand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Root mean square distance of the expected path from the nominal points (before: %1 µm)</source>
        <translation>Quadratischer Mittelwert des Abstands der erwarteten Bahn von den Nennpunkten (vorher: %1 µm)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>simulated machine, after</source>
        <translation>simulierte Maschine, nachher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The references run through the simulated machine (the true errors of the study), noise free</source>
        <translation>Die Sollwerte durch die simulierte Maschine geführt (die wahren Fehler der Studie), rauschfrei</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>largest correction</source>
        <translation>größte Korrektur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest |reference − nominal point|</source>
        <translation>Größter |Sollwert − Nennpunkt|</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Write the two edges&apos; deviations (mm) as a Q-DAS DFQ file, two characteristics</source>
        <translation>Die Abweichungen (mm) der beiden Kanten als Q-DAS-DFQ-Datei schreiben, zwei Merkmale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the edges machined along X and Y first</source>
        <translation>Zuerst die entlang X und Y bearbeiteten Kanten wählen</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Export compensated path as G-code</source>
        <translation>Kompensierte Bahn als G-Code exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>G-code (*.nc *.ngc *.gcode)</source>
        <translation>G-Code (*.nc *.ngc *.gcode)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export G-code</source>
        <translation>G-Code exportieren</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The kinematics study names no SPC series to export.</source>
        <translation>Die Kinematikstudie nennt keine SPC-Reihe zum Exportieren.</translation>
    </message>
    <message>
        <location line="+22"/>
        <location line="+5"/>
        <source>Export Q-DAS DFQ</source>
        <translation>Q-DAS-DFQ exportieren</translation>
    </message>
    <message>
        <location line="-3"/>
        <location line="+30"/>
        <source>Q-DAS DFQ files (*.dfq);;All files (*)</source>
        <translation>Q-DAS-DFQ-Dateien (*.dfq);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>Choose the edges machined along X and Y first.</source>
        <translation>Wählen Sie zuerst die entlang X und Y bearbeiteten Kanten.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Save the edges as Q-DAS DFQ</source>
        <translation>Kanten als Q-DAS-DFQ speichern</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save DFQ</source>
        <translation>DFQ speichern</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export compensated path as STEP-NC</source>
        <translation>Kompensierte Bahn als STEP-NC exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>STEP-NC Part 21 (*.p21 *.stp)</source>
        <translation>STEP-NC Part 21 (*.p21 *.stp)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export STEP-NC</source>
        <translation>STEP-NC exportieren</translation>
    </message>
</context>
<context>
    <name>metrofit::MachineDialog</name>
    <message>
        <location filename="../app/gui/machinedialog.cpp" line="+40"/>
        <source>Head-head XFYZBA (A and B on the head; the paper&apos;s machine)</source>
        <translation>Kopf-Kopf XFYZBA (A und B im Kopf; die Maschine der Veröffentlichung)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Table-table AC (A trunnion carrying a C table)</source>
        <translation>Tisch-Tisch AC (A-Schwenkbrücke mit C-Tisch)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Table-table BC (B trunnion carrying a C table)</source>
        <translation>Tisch-Tisch BC (B-Schwenkbrücke mit C-Tisch)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Head-table (B swivel head, C rotary table)</source>
        <translation>Kopf-Tisch (B-Schwenkkopf, C-Rundtisch)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Head-head geometry (Eq. 12–13)</source>
        <translation>Kopf-Kopf-Geometrie (Gl. 12–13)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt axis (table-table)</source>
        <translation>Schwenkachse (Tisch-Tisch)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Swivel head (head-table)</source>
        <translation>Schwenkkopf (Kopf-Tisch)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C axis of the rotary table</source>
        <translation>C-Achse des Rundtischs</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The kinematics the adjustment values are computed for</source>
        <translation>Die Kinematik, für die die Korrekturwerte berechnet werden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The control the controller frame is written for</source>
        <translation>Die Steuerung, für die der Steuerungs-Frame geschrieben wird</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Topology:</source>
        <translation>&amp;Topologie:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Control:</source>
        <translation>&amp;Steuerung:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>LX (cutter location in the A frame):</source>
        <translation>LX (Werkzeugposition im A-Koordinatensystem):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LY:</source>
        <translation>LY:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LZ:</source>
        <translation>LZ:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LAB (A origin in the B frame):</source>
        <translation>LAB (Ursprung von A im B-Koordinatensystem):</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A point on the tilt axis at the zero position (workpiece coordinates):</source>
        <translation>Ein Punkt auf der Schwenkachse in Nullstellung (Werkstückkoordinaten):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A point on the C axis at the zero position (workpiece coordinates):</source>
        <translation>Ein Punkt auf der C-Achse in Nullstellung (Werkstückkoordinaten):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Pivot length (B axis above the tool point):</source>
        <translation>Pivotlänge (B-Achse über der Werkzeugspitze):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Travel</source>
        <translation>Verfahrbereich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limited</source>
        <translation>Begrenzt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>always</source>
        <translation>immer</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Check the adjustment value S%1 against a travel</source>
        <translation>Den Korrekturwert S%1 gegen einen Verfahrbereich prüfen</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&amp;Preset</source>
        <translation>&amp;Vorgabe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The topology&apos;s default geometry and travel</source>
        <translation>Die Standardgeometrie und der Standardverfahrbereich der Topologie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Import…</source>
        <translation>&amp;Importieren…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read a machine JSON (as metrofit-cli match --machine-def reads) or a project</source>
        <translation>Eine Maschinen-JSON (wie metrofit-cli match --machine-def sie liest) oder ein Projekt lesen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E&amp;xport…</source>
        <translation>E&amp;xportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the machine JSON for metrofit-cli match --machine-def</source>
        <translation>Die Maschinen-JSON für metrofit-cli match --machine-def schreiben</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>B tilt axis (parallel to Y)</source>
        <translation>B-Schwenkachse (parallel zu Y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A tilt axis (parallel to X)</source>
        <translation>A-Schwenkachse (parallel zu X)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Travel of %1: the minimum %2° is above the maximum %3°.</source>
        <translation>Verfahrbereich von %1: das Minimum %2° liegt über dem Maximum %3°.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Travel of S%1: the minimum %2 mm is above the maximum %3 mm.</source>
        <translation>Verfahrbereich von S%1: das Minimum %2 mm liegt über dem Maximum %3 mm.</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 has no machine (studies.matching.machine).</source>
        <translation>%1 enthält keine Maschine (studies.matching.machine).</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Import a machine</source>
        <translation>Maschine importieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Machine or project (*.json *.metrofit);;All files (*)</source>
        <translation>Maschine oder Projekt (*.json *.metrofit);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export the machine</source>
        <translation>Maschine exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Machine JSON (*.json)</source>
        <translation>Maschinen-JSON (*.json)</translation>
    </message>
</context>
<context>
    <name>metrofit::MainWindow</name>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="+60"/>
        <source>Metrofit projects (*.metrofit)</source>
        <translation>Metrofit-Projekte (*.metrofit)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Autosave failed: %1</source>
        <translation>Automatische Sicherung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+7"/>
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
        <source>&amp;Import data…</source>
        <translation>Daten &amp;importieren…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Adds a file (thermal log, probe points, CMM report, …) to the project as a dataset</source>
        <translation>Fügt eine Datei (Thermoprotokoll, Tastpunkte, KMG-Bericht, …) als Datensatz zum Projekt hinzu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Recent files</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+192"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location line="-191"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export report PDF…</source>
        <translation>Bericht als PDF &amp;exportieren…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location line="-5"/>
        <location line="+8"/>
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
        <location line="+9"/>
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
        <source>&amp;Manual</source>
        <translation>&amp;Handbuch</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Shows the documentation: file formats, results, references</source>
        <translation>Zeigt die Dokumentation: Dateiformate, Ergebnisse, Quellen</translation>
    </message>
    <message>
        <location line="+4"/>
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
        <location line="+16"/>
        <source>%1[*] — Metrofit</source>
        <translation>%1[*] — Metrofit</translation>
    </message>
    <message>
        <location line="+34"/>
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
        <location line="+7"/>
        <source>Recovered the autosaved project; save it to keep it.</source>
        <translation>Das automatisch gesicherte Projekt wurde wiederhergestellt; speichern Sie es, um es zu behalten.</translation>
    </message>
    <message>
        <location line="-48"/>
        <source>Cannot save the setup model</source>
        <translation>Das Einrichtmodell kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>The setup model (relation graph) has unsaved edits. Do you want to save them?</source>
        <translation>Das Einrichtmodell (Beziehungsgraph) hat ungespeicherte Änderungen. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The project &quot;%1&quot; and the setup model (relation graph) have unsaved changes. Do you want to save them?</source>
        <translation>Das Projekt „%1“ und das Einrichtmodell (Beziehungsgraph) haben ungespeicherte Änderungen. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <location line="+140"/>
        <location line="+5"/>
        <location line="+5"/>
        <source>Cannot show the manual</source>
        <translation>Das Handbuch kann nicht angezeigt werden</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>The documentation is not installed; looked for:
%1</source>
        <translation>Die Dokumentation ist nicht installiert; gesucht in:
%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot read %1</source>
        <translation>%1 kann nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Import data</source>
        <translation>Daten importieren</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Cannot import the data</source>
        <translation>Die Daten können nicht importiert werden</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Imported %1 as “%2”</source>
        <translation>%1 als „%2“ importiert</translation>
    </message>
    <message>
        <location line="-219"/>
        <source>The project &quot;%1&quot; has unsaved changes. Do you want to save them?</source>
        <translation>Das Projekt „%1“ hat ungespeicherte Änderungen. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The project &quot;%1&quot; has unsaved changes, and the results of the last run are not saved either. Do you want to save them?</source>
        <translation>Das Projekt „%1“ hat ungespeicherte Änderungen, und auch die Ergebnisse der letzten Ausführung sind nicht gespeichert. Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The results of the last run are not saved in the project &quot;%1&quot; (they are lost when it is closed without saving). Do you want to save them?</source>
        <translation>Die Ergebnisse der letzten Ausführung sind im Projekt „%1“ nicht gespeichert (sie gehen verloren, wenn es ohne Speichern geschlossen wird). Möchten Sie sie speichern?</translation>
    </message>
    <message>
        <location line="+19"/>
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
        <location line="+13"/>
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
        <location line="+21"/>
        <source>Cannot save the project</source>
        <translation>Das Projekt kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="-16"/>
        <location line="+22"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Save project as</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <location line="+23"/>
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
        <location line="+10"/>
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
    <name>metrofit::ManualWindow</name>
    <message>
        <location filename="../app/gui/manual.cpp" line="+39"/>
        <source>Metrofit manual</source>
        <translation>Metrofit-Handbuch</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&amp;Back</source>
        <translation>&amp;Zurück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Contents</source>
        <translation>&amp;Inhalt</translation>
    </message>
</context>
<context>
    <name>metrofit::MatchingCurveView</name>
    <message>
        <location filename="../widgets/matching/matchingcurveview.cpp" line="+94"/>
        <source>generation</source>
        <translation>Generation</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>best RMS (mm)</source>
        <translation>beste RMS (mm)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Optimisation curve: run SADE or GA-simplex</source>
        <translation>Optimierungsverlauf: SADE oder GA-Simplex ausführen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Optimisation curve of the fine matching</source>
        <translation>Optimierungsverlauf der Feinausrichtung</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>least-squares optimum %1 mm</source>
        <translation>Optimum kleinster Quadrate %1 mm</translation>
    </message>
</context>
<context>
    <name>metrofit::MatchingPage</name>
    <message>
        <location filename="../app/gui/matchingpage.cpp" line="+127"/>
        <source>SADE (rough + fine, paper settings)</source>
        <translation>SADE (grob + fein, Originalparameter)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GA-simplex (rough + fine)</source>
        <translation>GA-Simplex (grob + fein)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Closed form (least-squares optimum)</source>
        <translation>Geschlossene Form (Optimum kleinster Quadrate)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Minimax (smallest largest deviation)</source>
        <translation>Minimax (kleinste größte Abweichung)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>closed form</source>
        <translation>geschlossene Form</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>minimax</source>
        <translation>Minimax</translation>
    </message>
    <message>
        <location line="+201"/>
        <source>Allow &amp;scale</source>
        <translation>&amp;Skalierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Run</source>
        <translation>A&amp;usführen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Save fr&amp;ame…</source>
        <translation>Fr&amp;ame speichern…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mac&amp;hine…</source>
        <translation>Masc&amp;hine…</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The posture shown after matching and used for the machine adjustment (every method is run for the comparison table)</source>
        <translation>Die nach der Ausrichtung angezeigte und für die Maschineneinstellung verwendete Lage (für die Vergleichstabelle wird jede Methode ausgeführt)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Symmetric tolerance ±T of every point (mm)</source>
        <translation>Symmetrische Toleranz ±T jedes Punktes (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit an isotropic scale too (e.g. thermal expansion of the part)</source>
        <translation>Zusätzlich einen isotropen Maßstab anpassen (z. B. Wärmedehnung des Werkstücks)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run every matching method on these points (Ctrl+R)</source>
        <translation>Alle Ausrichtungsmethoden auf diese Punkte anwenden (Strg+R)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the running SADE / GA-simplex search (Esc)</source>
        <translation>Die laufende SADE- / GA-Simplex-Suche anhalten (Esc)</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rx (deg)</source>
        <translation>rx (Grad)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ry (deg)</source>
        <translation>ry (Grad)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rz (deg)</source>
        <translation>rz (Grad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>z (mm)</source>
        <translation>z (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>scale</source>
        <translation>Maßstab</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+35"/>
        <source>RMSE (mm)</source>
        <translation>RMSE (mm)</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>max |d| (mm)</source>
        <translation>max |d| (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out before</source>
        <translation>außerhalb vorher</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out after</source>
        <translation>außerhalb nachher</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time (ms)</source>
        <translation>Zeit (ms)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The machine the adjustment values are for: topology, geometry, travel and control (Ctrl+Shift+M)</source>
        <translation>Die Maschine, für die die Korrekturwerte gelten: Topologie, Geometrie, Verfahrbereich und Steuerung (Strg+Umschalt+M)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Round</source>
        <translation>Runde</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max |d| measured (mm)</source>
        <translation>max |d| gemessen (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out of tolerance</source>
        <translation>außerhalb der Toleranz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SX (mm)</source>
        <translation>SX (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SY (mm)</source>
        <translation>SY (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>true max |d| (mm)</source>
        <translation>wahres max |d| (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>true out of tolerance</source>
        <translation>wirklich außerhalb der Toleranz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SZ (mm)</source>
        <translation>SZ (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rotary 1 (deg)</source>
        <translation>Drehachse 1 (Grad)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rotary 2 (deg)</source>
        <translation>Drehachse 2 (Grad)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>frame rot. (deg)</source>
        <translation>Koord.-Drehung (Grad)</translation>
    </message>
    <message>
        <location line="+11"/>
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
        <location line="+0"/>
        <source>Deviation after (mm)</source>
        <translation>Abweichung nachher (mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Export deviations after matching (CSV)…</source>
        <translation>Abweichungen nach dem Einpassen &amp;exportieren (CSV)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Each point&apos;s signed deviation along its normal and its deviation vector after the fit: id, surface, d_mm, dx_mm, dy_mm, dz_mm</source>
        <translation>Die vorzeichenbehaftete Abweichung jedes Punkts entlang seiner Normalen und sein Abweichungsvektor nach dem Einpassen: id, surface, d_mm, dx_mm, dy_mm, dz_mm</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The control the frame is written for: HEIDENHAIN datum shift and PLANE SPATIAL, SINUMERIK TRANS and AROT, FANUC G68.2</source>
        <translation>Die Steuerung, für die der Frame geschrieben wird: HEIDENHAIN Nullpunktverschiebung und PLANE SPATIAL, SINUMERIK TRANS und AROT, FANUC G68.2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Decimals of the values in mm and ° (FANUC IS-B takes 3)</source>
        <translation>Nachkommastellen der Werte in mm und ° (FANUC IS-B nimmt 3)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The blocks that set the frame; the saved program adds its frame and comments</source>
        <translation>Die Sätze, die den Frame setzen; das gespeicherte Programm ergänzt Programmrahmen und Kommentare</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Controller frame</source>
        <translation>Steuerungs-Frame</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Contro&amp;l:</source>
        <translation>Steueru&amp;ng:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Decimals:</source>
        <translation>&amp;Nachkommastellen:</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Methods and &amp;machine</source>
        <translation>Methoden und &amp;Maschine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Optimisation curve</source>
        <translation>&amp;Optimierungsverlauf</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;measure loop</source>
        <translation>&amp;Nachmessschleife</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Points</source>
        <translation>&amp;Punkte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Controller frame</source>
        <translation>Steuerungs-&amp;Frame</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;Probe points:</source>
        <translation>&amp;Antastpunkte:</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>M&amp;ethod:</source>
        <translation>M&amp;ethode:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Tolerance ±</source>
        <translation>&amp;Toleranz ±</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Lock:</source>
        <translation>Sperren:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Hold %1 at 0 (a constrained optimum over the other parameters)</source>
        <translation>%1 auf 0 halten (ein beschränktes Optimum über die übrigen Parameter)</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Change the matching method</source>
        <translation>Ausrichtungsmethode ändern</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Change the matching tolerance</source>
        <translation>Ausrichtungstoleranz ändern</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Change the matching scale</source>
        <translation>Skalierung der Ausrichtung ändern</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Change the matching locks</source>
        <translation>Sperren der Ausrichtung ändern</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Change the control of the frame</source>
        <translation>Steuerung des Frames ändern</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>Change the decimals of the frame</source>
        <translation>Nachkommastellen des Frames ändern</translation>
    </message>
    <message>
        <location line="+63"/>
        <location line="+314"/>
        <location line="+62"/>
        <source>Matching failed: %1</source>
        <translation>Die Ausrichtung ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+500"/>
        <source>No posture yet: press Run (Ctrl+R).</source>
        <translation>Noch keine Lage: Ausführen drücken (Strg+R).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>There is no posture to write yet: run the matching first (Ctrl+R)</source>
        <translation>Es gibt noch keine Lage zum Schreiben: zuerst die Ausrichtung ausführen (Strg+R)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Datum shift (CYCL DEF 7) to the origin t, then PLANE SPATIAL with R = Rz(SPC) Ry(SPB) Rx(SPA) about the non-tilted axes; STAY: no axis moves. Call the saved program (CALL PGM) once the part&apos;s preset is active.</source>
        <translation>Nullpunktverschiebung (CYCL DEF 7) zum Ursprung t, dann PLANE SPATIAL mit R = Rz(SPC) Ry(SPB) Rx(SPA) um die ungeschwenkten Achsen; STAY: keine Achse bewegt sich. Das gespeicherte Programm (CALL PGM) aufrufen, sobald der Bezugspunkt des Werkstücks aktiv ist.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>TRANS to the origin t on top of the active settable frame (G54 …), then AROT about Z, Y&apos;, X&apos;&apos;: R = Rz(Z) Ry(Y) Rx(X). The tool is not oriented: use CYCLE800 or TRAORI for that.</source>
        <translation>TRANS zum Ursprung t auf den aktiven einstellbaren Frame (G54 …), dann AROT um Z, Y&apos;, X&apos;&apos;: R = Rz(Z) Ry(Y) Rx(X). Das Werkzeug wird nicht ausgerichtet: dafür CYCLE800 oder TRAORI verwenden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>G68.2 with the origin t and the Euler angles R = Rz(I) Rx(J) Rz(K), cancelled with G69. G53.1 is not written: it moves the rotary axes, program it at a safe position.</source>
        <translation>G68.2 mit dem Ursprung t und den Euler-Winkeln R = Rz(I) Rx(J) Rz(K), aufgehoben mit G69. G53.1 wird nicht geschrieben: es bewegt die Drehachsen, an einer sicheren Position programmieren.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Posture of %1 as a controller frame (mm, °).</source>
        <translation>Lage von %1 als Steuerungs-Frame (mm, °).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The fitted scale %1 is not applied: no control frame scales.</source>
        <translation>Der angepasste Maßstab %1 wird nicht angewandt: kein Steuerungs-Frame skaliert.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Write the frame program for the control to a file (as metrofit-cli match --frame does)</source>
        <translation>Das Frame-Programm für die Steuerung in eine Datei schreiben (wie metrofit-cli match --frame)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot write the posture as a frame: %1</source>
        <translation>Die Lage kann nicht als Frame geschrieben werden: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>There is no posture to write yet: run the matching first.</source>
        <translation>Es gibt noch keine Lage zum Schreiben: zuerst die Ausrichtung ausführen.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>There are no deviations after matching yet: run the matching first.</source>
        <translation>Es gibt noch keine Abweichungen nach dem Einpassen: zuerst das Einpassen ausführen.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export the deviations after matching</source>
        <translation>Abweichungen nach dem Einpassen exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot export the deviations</source>
        <translation>Die Abweichungen können nicht exportiert werden</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>HEIDENHAIN programs (*.h)</source>
        <translation>HEIDENHAIN-Programme (*.h)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SINUMERIK subprograms (*.spf)</source>
        <translation>SINUMERIK-Unterprogramme (*.spf)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FANUC programs (*.nc)</source>
        <translation>FANUC-Programme (*.nc)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save the controller frame</source>
        <translation>Steuerungs-Frame speichern</translation>
    </message>
    <message>
        <location line="-18"/>
        <location line="+19"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot save the frame</source>
        <translation>Der Frame kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="-837"/>
        <source>The effects applied to the matching model are invalid:
%1</source>
        <translation>Die ins Ausrichtungsmodell übernommenen Effekte sind ungültig:
%1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 points on %2 surfaces, %3%4.</source>
        <translation>%1 Punkte auf %2 Flächen, %3%4.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Includes applied effects: %1 (the nominal points are deformed by them before matching).</source>
        <translation>Enthält übernommene Effekte: %1 (die Nennpunkte werden vor der Ausrichtung durch sie verformt).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Effects applied on the Diagnosis page belong to the probe points %1 (the ones the diagnosis ran on); these points use the declared model.</source>
        <translation>Die auf der Seite „Diagnose“ übernommenen Effekte gehören zu den Antastpunkten %1 (auf denen die Diagnose lief); diese Punkte verwenden das deklarierte Modell.</translation>
    </message>
    <message>
        <location line="-105"/>
        <location line="+208"/>
        <source>Settings changed: press Run (Ctrl+R) to match again.</source>
        <translation>Einstellungen geändert: Ausführen (Strg+R) drücken, um erneut auszurichten.</translation>
    </message>
    <message>
        <location line="-917"/>
        <source>studies.matching.tolerance_mm: %1 mm cannot be set on the page (it takes %2 to %3 mm in steps of %4 mm)</source>
        <translation>studies.matching.tolerance_mm: %1 mm kann auf der Seite nicht eingestellt werden (sie nimmt %2 bis %3 mm in Schritten von %4 mm)</translation>
    </message>
    <message>
        <location line="+761"/>
        <source>This project has no probe points. Import them with File › Import data… (Ctrl+I): probe points with their nominals, a hole table or a CMM report, or raw measured points whose nominals come from a fitted element or a second measurement.</source>
        <translation>Dieses Projekt hat keine Antastpunkte. Importieren Sie sie mit Datei › Daten importieren… (Strg+I): Antastpunkte mit ihren Sollpunkten, eine Bohrungstabelle oder ein KMG-Protokoll, oder rohe Messpunkte, deren Sollpunkte aus einem angepassten Element oder einer zweiten Messung kommen.</translation>
    </message>
    <message>
        <location line="+150"/>
        <source>The matching study&apos;s settings are invalid, nothing is run until they are corrected (Undo, or the project file): %1</source>
        <translation>Die Einstellungen der Ausrichtungsstudie sind ungültig; nichts wird ausgeführt, bis sie korrigiert sind (Rückgängig oder die Projektdatei): %1</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Lock %1 and run</source>
        <translation>%1 sperren und ausführen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The points cannot determine %1 (a sphere fixes no rotation, parallel normals fix no rotation about them): hold them at 0 and run again. Undo gives the locks back.</source>
        <translation>Die Punkte bestimmen %1 nicht (eine Kugel legt keine Drehung fest, parallele Normalen keine Drehung um sie): bei 0 halten und erneut ausführen. Rückgängig nimmt die Sperren zurück.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Lock %1</source>
        <translation>%1 sperren</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Matching …</source>
        <translation>Ausrichtung läuft …</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Match the probe points %1</source>
        <translation>Die Antastpunkte %1 ausrichten</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>The stored result (computed %1) is out of date: the matching settings changed since. Not matched with these settings yet: press Run (Ctrl+R).</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Ausrichtungseinstellungen haben sich seitdem geändert. Mit diesen Einstellungen noch nicht ausgerichtet: Ausführen drücken (Strg+R).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the points file changed since. Press Run (Ctrl+R) to match the points as they are now.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Punktedatei hat sich seitdem geändert. Ausführen (Strg+R) drücken, um die Punkte in ihrem jetzigen Stand auszurichten.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the points file cannot be read.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) kann nicht geprüft werden: die Punktedatei ist nicht lesbar.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>From the saved project, computed %1 with these settings on these points: %2: %3 of %4 points out of ±%5 mm before, %6 after; RMSE %7 mm, max |d| %8 mm. Press Run (Ctrl+R) to see the views.</source>
        <translation>Aus dem gespeicherten Projekt, berechnet %1 mit diesen Einstellungen auf diesen Punkten: %2: %3 von %4 Punkten außerhalb ±%5 mm vorher, %6 nachher; RMSE %7 mm, max |d| %8 mm. Ausführen (Strg+R) drücken, um die Ansichten zu sehen.</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>(The loop ran with the previous tolerance: Run again.)</source>
        <translation>(Die Schleife lief mit der vorherigen Toleranz: erneut ausführen.)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 of %3 points out of ±%4 mm before, %5 after; RMSE %6 mm, max |d| %7 mm.%8</source>
        <translation>%1: %2 von %3 Punkten außerhalb ±%4 mm vorher, %5 nachher; RMSE %6 mm, max |d| %7 mm.%8</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> Cancelled: the best posture found so far.</source>
        <translation> Abgebrochen: die bisher beste gefundene Lage.</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>BEFORE matching
%1 of %2 out of ±%3 mm, max |d| %4 mm</source>
        <translation>VOR der Ausrichtung
%1 von %2 außerhalb ±%3 mm, max |d| %4 mm</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>AFTER matching
not run yet: press Run (Ctrl+R)</source>
        <translation>NACH der Ausrichtung
noch nicht ausgeführt: Ausführen drücken (Strg+R)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>AFTER matching (%1)
%2 of %3 out of ±%4 mm, max |d| %5 mm</source>
        <translation>NACH der Ausrichtung (%1)
%2 von %3 außerhalb ±%4 mm, max |d| %5 mm</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Shown after matching and used for the machine adjustment</source>
        <translation>Nach der Ausrichtung angezeigt und für die Maschineneinstellung verwendet</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Rough</source>
        <translation>Grob</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rough matching: 3-point local frames, Eq. 3–7</source>
        <translation>Grobausrichtung: lokale 3-Punkt-Koordinatensysteme, Gl. 3–7</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 is locked at %2: the rough stage&apos;s three-point frames cannot hold a lock, the fine stage (SADE) holds it.</source>
        <translation>%1 ist bei %2 gesperrt: Die Dreipunkt-Koordinatensysteme der Grobausrichtung können keine Sperre halten, die Feinausrichtung (SADE) hält sie.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>head-head, Eq. 12–13</source>
        <translation>Kopf-Kopf, Gl. 12–13</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>table-table trunnion</source>
        <translation>Tisch-Tisch, Schwenkbrücke</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B swivel head, C rotary table</source>
        <translation>B-Schwenkkopf, C-Rundtisch</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the project&apos;s machine %1 (%2)</source>
        <translation>die Maschine des Projekts %1 (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the default machine %1 (%2): no machine is defined for this project; enter yours with Machine… (Ctrl+Shift+M) before using these values at the control</source>
        <translation>die Standardmaschine %1 (%2): für dieses Projekt ist keine Maschine definiert; geben Sie Ihre mit Maschine… (Strg+Umschalt+M) ein, bevor Sie diese Werte an der Steuerung verwenden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Adjustment values will be for %1.</source>
        <translation>Die Korrekturwerte gelten für %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Machine adjustment values for %1, posture of %2. %3</source>
        <translation>Maschinen-Korrekturwerte für %1, Lage von %2. %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Within travel.</source>
        <translation>Innerhalb des Verfahrwegs.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OUTSIDE TRAVEL: %1</source>
        <translation>AUSSERHALB DES VERFAHRWEGS: %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+2"/>
        <source>Change the machine</source>
        <translation>Maschine ändern</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Change the controller frame</source>
        <translation>Steuerungs-Frame ändern</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>deg</source>
        <translation>Grad</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>frame rotation</source>
        <translation>Drehung des Koordinatensystems</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The remeasure loop did not run.</source>
        <translation>Die Nachmessschleife wurde nicht ausgeführt.</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+2"/>
        <source>S%1 (deg)</source>
        <translation>S%1 (Grad)</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>Every point is inside the tolerance after %n adjustment(s); the true remaining error is %1 mm at most.</source>
        <translation>
            <numerusform>Nach %n Korrektur liegt jeder Punkt in der Toleranz; der wahre Restfehler beträgt höchstens %1 mm.</numerusform>
            <numerusform>Nach %n Korrekturen liegt jeder Punkt in der Toleranz; der wahre Restfehler beträgt höchstens %1 mm.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>FAILED: the best fit leaves points out of tolerance (form error larger than the tolerance); no WCS adjustment can bring them in. True remaining error %1 mm, %2 point(s) out.</source>
        <translation>FEHLGESCHLAGEN: die beste Einpassung lässt Punkte außerhalb der Toleranz (Formfehler größer als die Toleranz); keine WKS-Korrektur kann sie hineinbringen. Wahrer Restfehler %1 mm, %2 Punkt(e) außerhalb.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>FAILED: the adjustment is beyond the machine&apos;s travel (%1); the WCS was not moved. True remaining error %2 mm.</source>
        <translation>FEHLGESCHLAGEN: die Korrektur liegt außerhalb des Verfahrbereichs der Maschine (%1); das WKS wurde nicht verschoben. Wahrer Restfehler %2 mm.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>FAILED: still out of tolerance after the last adjustment. True remaining error %1 mm.</source>
        <translation>FEHLGESCHLAGEN: nach der letzten Korrektur weiterhin außerhalb der Toleranz. Wahrer Restfehler %1 mm.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stopped before the end.</source>
        <translation>Vor dem Ende angehalten.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Step 7 with the simulator as machine and CMM (the part where the probe found it, with its form error; the %1 fit does not place it; probing noise %2 mm): measure, match, adjust the WCS, remeasure. %3</source>
        <translation>Schritt 7 mit dem Simulator als Maschine und KMG (das Teil dort, wo der Taster es fand, mit seinem Formfehler; die %1-Einpassung platziert es nicht; Antastrauschen %2 mm): messen, einpassen, WKS korrigieren, nachmessen. %3</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>stopped: %1</source>
        <translation>angehalten: %1</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>in tolerance: no adjustment</source>
        <translation>in Toleranz: keine Einstellung</translation>
    </message>
    <message>
        <location line="-654"/>
        <source>with normals</source>
        <translation>mit Normalen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>positions only</source>
        <translation>nur Positionen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, planar</source>
        <translation>, eben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Licence: %1.</source>
        <translation>Lizenz: %1.</translation>
    </message>
    <message>
        <location line="-94"/>
        <location line="+111"/>
        <location line="+55"/>
        <source>Not matched yet: press Run (Ctrl+R).</source>
        <translation>Noch nicht ausgerichtet: Ausführen drücken (Strg+R).</translation>
    </message>
    <message>
        <location line="-45"/>
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
        <location filename="../app/gui/overviewpage.cpp" line="+31"/>
        <source>Project overview</source>
        <translation>Projektübersicht</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+110"/>
        <source>Project name</source>
        <translation>Projektname</translation>
    </message>
    <message>
        <location line="-108"/>
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
        <location line="+12"/>
        <source>&lt;b&gt;New here?&lt;/b&gt; Open the demo project: sample data for every study (setup correction, posture matching, kinematics &amp;amp; SPC, thermal, diagnosis) to try each page. It is also in &lt;i&gt;Help › Open demo project&lt;/i&gt;.</source>
        <translation>&lt;b&gt;Neu hier?&lt;/b&gt; Öffnen Sie das Demoprojekt: Beispieldaten für jede Studie (Einrichtdatenkorrektur, Lageausrichtung, Kinematik &amp;amp; SPC, Thermik, Diagnose), um jede Seite auszuprobieren. Es ist auch unter &lt;i&gt;Hilfe › Demoprojekt öffnen&lt;/i&gt; zu finden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Open the demo project</source>
        <translation>&amp;Demoprojekt öffnen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Copies the bundled demo project into a folder of your own and opens it</source>
        <translation>Kopiert das mitgelieferte Demoprojekt in einen eigenen Ordner und öffnet es</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Hide this hint (it does not come back)</source>
        <translation>Diesen Hinweis ausblenden (er erscheint nicht wieder)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>&amp;Import data…</source>
        <translation>Daten &amp;importieren…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Adds a file to the project as a dataset (File › Import data…, Ctrl+I, or drop files on the window); right-click a dataset to rename, re-link or remove it</source>
        <translation>Fügt eine Datei als Datensatz zum Projekt hinzu (Datei › Daten importieren…, Strg+I, oder Dateien auf das Fenster ziehen); Rechtsklick auf einen Datensatz: umbenennen, neu verknüpfen oder entfernen</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>not saved yet</source>
        <translation>noch nicht gespeichert</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Study settings the methods cannot use; correct them in the project file:</source>
        <translation>Studien-Einstellungen, die die Verfahren nicht verwenden können; korrigieren Sie sie in der Projektdatei:</translation>
    </message>
</context>
<context>
    <name>metrofit::PointSetView</name>
    <message>
        <location filename="../widgets/matching/pointsetview.cpp" line="+362"/>
        <source>deviation
(mm)</source>
        <translation>Abw.
(mm)</translation>
    </message>
    <message>
        <location line="+231"/>
        <source>grey: nominal points; coloured: measured, deviation vectors x%1</source>
        <translation>grau: Nennpunkte; farbig: gemessen, Abweichungsvektoren x%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>after matching: solid; before (nominal and measured): faded</source>
        <translation>nach der Ausrichtung: kräftig; vorher (Nenn- und Messpunkte): blass</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the part: coloured as the nearest probed point, light grey where none is near</source>
        <translation>das Teil: gefärbt wie der nächste Antastpunkt, hellgrau, wo keiner nahe ist</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>green: within ±%1 mm; large: out of tolerance</source>
        <translation>grün: innerhalb ±%1 mm; groß: außerhalb der Toleranz</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>3D view needs an X11 display (run under xvfb-run for headless use)</source>
        <translation>Die 3D-Ansicht benötigt eine X11-Anzeige (ohne Bildschirm unter xvfb-run starten)</translation>
    </message>
</context>
<context>
    <name>metrofit::PolarDeviationView</name>
    <message>
        <location filename="../widgets/kinematics/kinematicsviews.cpp" line="-115"/>
        <source>%1
angle: %2°
deviation: %3 µm</source>
        <translation>%1
Winkel: %2°
Abweichung: %3 µm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CCW</source>
        <translation>GUZ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CW</source>
        <translation>UZ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>expected after compensation</source>
        <translation>erwartet nach Kompensation</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Radial deviation of the measured path from the nominal circle, magnified (ballbar plot): plotted radius = R + k × deviation. Blue: CCW loop, orange: CW loop; the rings are labelled in µm.</source>
        <translation>Radiale Abweichung der gemessenen Bahn vom Nennkreis, vergrößert (Ballbar-Diagramm): dargestellter Radius = R + k × Abweichung. Blau: Umlauf gegen den Uhrzeigersinn, orange: im Uhrzeigersinn; die Ringe sind in µm beschriftet.</translation>
    </message>
</context>
<context>
    <name>metrofit::PreferencesDialog</name>
    <message>
        <location filename="../app/gui/preferencesdialog.cpp" line="+19"/>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System</source>
        <translation>System</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>While the project has unsaved changes, a copy is written next to it this often, and offered for recovery after a crash (0: off)</source>
        <translation>Solange das Projekt ungespeicherte Änderungen hat, wird in diesem Abstand eine Kopie daneben geschrieben und nach einem Absturz zur Wiederherstellung angeboten (0: aus)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The language is applied at the next start of Metrofit.</source>
        <translation>Die Sprache wird beim nächsten Start von Metrofit übernommen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Autosave every:</source>
        <translation>&amp;Automatisch sichern alle:</translation>
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
        <location filename="../widgets/document/projectdocument.cpp" line="+35"/>
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
        <location line="+200"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location line="+160"/>
        <source>the project has not been saved yet; choose a file name with Save As</source>
        <translation>das Projekt wurde noch nicht gespeichert; wählen Sie mit „Speichern unter“ einen Dateinamen</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>the project has no dataset &apos;%1&apos;</source>
        <translation>das Projekt hat keinen Datensatz „%1“</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+26"/>
        <source>a dataset needs an id</source>
        <translation>ein Datensatz braucht eine Kennung</translation>
    </message>
    <message>
        <location line="-23"/>
        <location line="+26"/>
        <source>the project already has a dataset &apos;%1&apos;</source>
        <translation>das Projekt hat bereits einen Datensatz „%1“</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>Import dataset %1</source>
        <translation>Datensatz %1 importieren</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Remove dataset %1</source>
        <translation>Datensatz %1 entfernen</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Rename dataset %1 to %2</source>
        <translation>Datensatz %1 in %2 umbenennen</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Re-link dataset %1</source>
        <translation>Datensatz %1 neu verknüpfen</translation>
    </message>
</context>
<context>
    <name>metrofit::ProjectNavigator</name>
    <message>
        <location filename="../app/gui/projectnavigator.cpp" line="+91"/>
        <source>Add report features to setup model…</source>
        <translation>Merkmale des Berichts zum Einrichtmodell hinzufügen…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Create setup model from report…</source>
        <translation>Einrichtmodell aus dem Bericht erstellen…</translation>
    </message>
    <message>
        <location line="+34"/>
        <location line="+39"/>
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
    <name>metrofit::Report</name>
    <message>
        <location filename="../widgets/report/diagnosissection.cpp" line="+42"/>
        <location filename="../widgets/report/thermalsection.cpp" line="+743"/>
        <source>Thermal</source>
        <translation>Thermik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kinematic</source>
        <translation>Kinematik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setup data</source>
        <translation>Einrichtdaten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Posture matching</source>
        <translation>Lageausrichtung</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>form %1</source>
        <translation>Form %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>rmse %1 %2, max |e| %3 %2</source>
        <translation>rmse %1 %2, max |e| %3 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, held-out rmse %1 %2</source>
        <translation>, rmse Testdaten %1 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>rmse %1 %2</source>
        <translation>RMSE %1 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, held-out %1 %2</source>
        <translation>, zurückgehalten %1 %2</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <source>The diagnosis could not run: %1</source>
        <translation>Die Diagnose konnte nicht ausgeführt werden: %1</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+113"/>
        <source>Closed loop: %1</source>
        <translation>Geschlossener Regelkreis: %1</translation>
    </message>
    <message>
        <location line="-111"/>
        <location line="+133"/>
        <source>not checked</source>
        <translation>nicht geprüft</translation>
    </message>
    <message>
        <location line="-132"/>
        <source>Correct the diagnosis settings of this study.</source>
        <translation>Korrigieren Sie die Diagnose-Einstellungen dieser Studie.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Declared model: %1 a static linear function of %2, fitted on the first %3 % of the rows and held out on the rest.</source>
        <translation>Deklariertes Modell: %1 als statische lineare Funktion von %2, angepasst an den ersten %3 % der Zeilen, der Rest dient als Testdaten.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Declared model: the Cartesian machine&apos;s actuator errors (origin, axis angles).</source>
        <translation>Deklariertes Modell: die Antriebsfehler der kartesischen Maschine (Ursprung, Achswinkel).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Declared model: constant setup-data errors acting through the relation graph of %1.</source>
        <translation>Deklariertes Modell: konstante Einrichtdatenfehler, die über den Beziehungsgraphen von %1 wirken.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Declared model: a rigid posture error (rotation and translation); tolerance ±%1 mm.</source>
        <translation>Deklariertes Modell: ein starrer Lagefehler (Rotation und Translation); Toleranz ±%1 mm.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Step 0, the declared model: %1.</source>
        <translation>Schritt 0, das deklarierte Modell: %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>effect</source>
        <translation>Effekt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>parameters ± standard error</source>
        <translation>Parameter ± Standardfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rmse (%1)</source>
        <translation>rmse (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>held-out (%1)</source>
        <translation>Testdaten (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accepted</source>
        <translation>übernommen</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../widgets/report/kinematicsection.cpp" line="+119"/>
        <location line="+138"/>
        <location filename="../widgets/report/thermalsection.cpp" line="-418"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../widgets/report/kinematicsection.cpp" line="-138"/>
        <location line="+138"/>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Evidence, per candidate (# = loop round):</source>
        <translation>Evidenz je Kandidat (# = Runde der Schleife):</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No candidate passed the evidence test: the declared model is kept. %1.</source>
        <translation>Kein Kandidat hat den Evidenztest bestanden: das deklarierte Modell bleibt. %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Accepted: %1. Final model: %2.</source>
        <translation>Übernommen: %1. Endgültiges Modell: %2.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Residual before and after %1</source>
        <translation>Residuen vor und nach %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../widgets/report/thermalsection.cpp" line="+253"/>
        <source>error (%1)</source>
        <translation>Fehler (%1)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>declared model</source>
        <translation>deklariertes Modell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>with accepted effects</source>
        <translation>mit übernommenen Effekten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rmse (fitted data)</source>
        <translation>rmse (Anpassungsdaten)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max |e| (fitted data)</source>
        <translation>max |e| (Anpassungsdaten)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>rmse (held-out rows)</source>
        <translation>rmse (Testdaten)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: no effect beyond the declared model is supported by the data.</source>
        <translation>%1: Die Daten stützen keinen Effekt über das deklarierte Modell hinaus.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the declared model lacks %2.</source>
        <translation>%1: Dem deklarierten Modell fehlt %2.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Still unexplained: %1</source>
        <translation>Noch unerklärt: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add %1 to the model (Apply on the Diagnosis page).</source>
        <translation>Nehmen Sie %1 ins Modell auf (Übernehmen auf der Seite Diagnose).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add %1 to the model (Apply on the Diagnosis page), then look for the cause of what is still unexplained before trusting the compensation further.</source>
        <translation>Nehmen Sie %1 ins Modell auf (Übernehmen auf der Seite Diagnose) und suchen Sie die Ursache des noch Unerklärten, bevor Sie der Kompensation weiter vertrauen.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Keep the declared model: its residual is noise.</source>
        <translation>Behalten Sie das deklarierte Modell: Sein Residuum ist Rauschen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the declared model, and look for the cause of what is still unexplained (a variable not recorded, a change in the process).</source>
        <translation>Behalten Sie das deklarierte Modell und suchen Sie die Ursache des noch Unerklärten (eine nicht erfasste Größe, eine Änderung im Prozess).</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Final residual against %1</source>
        <translation>Endgültiges Residuum über %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Final residual against %1 with the generic fit (%2)</source>
        <translation>Endgültiges Residuum über %1 mit der generischen Anpassung (%2)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Closed loop: diagnosis</source>
        <translation>Geschlossener Kreis: Diagnose</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>For each study the declared model is fitted and its residual computed; candidate effects the model lacks are tried one by one, each estimated with its parameters and their standard errors. An effect is accepted only on evidence (out-of-sample improvement for thermal, an information criterion with a conservative threshold elsewhere) and when it reduces the error by a practically relevant amount; the model is refitted with it and the search repeated until nothing more is found.</source>
        <translation>Für jede Studie wird das deklarierte Modell angepasst und sein Residuum berechnet; Kandidateneffekte, die dem Modell fehlen, werden einzeln getestet und jeweils mit ihren Parametern und deren Standardfehlern geschätzt. Ein Effekt wird nur bei ausreichender Evidenz übernommen (Verbesserung auf den Testdaten bei Thermik, sonst ein Informationskriterium mit konservativer Schwelle) und wenn er den Fehler praktisch relevant verringert; das Modell wird mit ihm neu angepasst und die Suche wiederholt, bis nichts mehr gefunden wird.</translation>
    </message>
    <message>
        <location filename="../widgets/report/kinematicsection.cpp" line="-214"/>
        <location line="+267"/>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location line="-267"/>
        <source>identified</source>
        <translation>identifiziert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>standard error</source>
        <translation>Standardfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulated (true)</source>
        <translation>simuliert (wahr)</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+270"/>
        <source>origin x (µm)</source>
        <translation>Ursprung x (µm)</translation>
    </message>
    <message>
        <location line="-268"/>
        <location line="+270"/>
        <source>origin y (µm)</source>
        <translation>Ursprung y (µm)</translation>
    </message>
    <message>
        <location line="-268"/>
        <location line="+269"/>
        <source>X axis angle a (deg)</source>
        <translation>Winkel der X-Achse a (Grad)</translation>
    </message>
    <message>
        <location line="-267"/>
        <location line="+269"/>
        <source>Y axis angle b (deg)</source>
        <translation>Winkel der Y-Achse b (Grad)</translation>
    </message>
    <message>
        <location line="-267"/>
        <location line="+269"/>
        <source>squareness b − a (deg)</source>
        <translation>Rechtwinkligkeit b − a (Grad)</translation>
    </message>
    <message>
        <location line="-267"/>
        <source>RMS residual (µm)</source>
        <translation>RMS-Residuum (µm)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>ISO 230-4 results</source>
        <translation>Ergebnisse nach ISO 230-4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Per direction: the circular deviation G (radial range about the path&apos;s own least-squares centre) and the radial deviation F (largest and smallest deviation from the nominal radius about the nominal centre).</source>
        <translation>Je Richtung: die Kreisformabweichung G (radiale Spanne um den eigenen Ausgleichskreismittelpunkt der Bahn) und die Radialabweichung F (größte und kleinste Abweichung vom Nennradius um den Nennmittelpunkt).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>G (µm)</source>
        <translation>G (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>F max (µm)</source>
        <translation>F max (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>F min (µm)</source>
        <translation>F min (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>LSQ centre (mm)</source>
        <translation>Ausgleichskreismittelpunkt (mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CCW</source>
        <translation>GUZ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CW</source>
        <translation>UZ</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Circular hysteresis H (largest radial difference between the CW and the CCW path at the same angle, about one least-squares centre): %1 µm.</source>
        <translation>Umkehrspanne H (größte radiale Differenz zwischen der Bahn im Uhrzeigersinn und der im Gegenuhrzeigersinn beim selben Winkel, um einen gemeinsamen Ausgleichskreismittelpunkt): %1 µm.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Circular hysteresis H: not available (the test has one direction only).</source>
        <translation>Umkehrspanne H: nicht verfügbar (der Test hat nur eine Richtung).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ballbar breakdown</source>
        <translation>Ballbar-Aufschlüsselung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not available: %1.</source>
        <translation>Nicht verfügbar: %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The radial deviation of %1 fitted by least squares to the signature of each cause, after the centre and radius of each run; ranked by share, the part of the radial deviation&apos;s variance the cause explains. A cause is above the noise when its value exceeds three standard errors.</source>
        <translation>Die radiale Abweichung %1, nach der Methode der kleinsten Quadrate an die Signatur jeder Ursache angepasst, nach Mittelpunkt und Radius jedes Laufs; geordnet nach Anteil, dem Teil der Varianz der radialen Abweichung, den die Ursache erklärt. Eine Ursache liegt über dem Rauschen, wenn ihr Wert drei Standardfehler übersteigt.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>both runs (CCW and CW)</source>
        <translation>beider Läufe (CCW und CW)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the one run (without the reversal causes, which need both directions)</source>
        <translation>des einen Laufs (ohne die Umkehrursachen, die beide Richtungen brauchen)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cause</source>
        <translation>Ursache</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>value (µm)</source>
        <translation>Wert (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>± std. error (µm)</source>
        <translation>± Standardfehler (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>share (%)</source>
        <translation>Anteil (%)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>above the noise</source>
        <translation>über dem Rauschen</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+313"/>
        <source>Circular test “%1”</source>
        <translation>Kreisformtest „%1“</translation>
    </message>
    <message>
        <location line="-305"/>
        <source>%1 points; nominal circle R %2 mm about (%3, %4) mm; %5 loops (CCW, then CW). The actuator errors of the Cartesian machine (%8, Eq. 9: P = o + ir·x + jr·y, ir = (cos a, sin a), jr = (−sin b, cos b)) were identified by Levenberg-Marquardt (%6, iterations: %7); standard errors from the residuals.</source>
        <translation>%1 Punkte; Nennkreis R %2 mm um (%3; %4) mm; %5 Umläufe (gegen, dann mit dem Uhrzeigersinn). Die Antriebsfehler der kartesischen Maschine (%8, Gl. 9: P = o + ir·x + jr·y, ir = (cos a, sin a), jr = (−sin b, cos b)) wurden mit Levenberg-Marquardt bestimmt (%6, Iterationen: %7); Standardfehler aus den Residuen.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Includes applied effects: %1 (added with Apply on the diagnosis page). The errors above were identified with them and the compensated references include their corrections.</source>
        <translation>Enthält übernommene Effekte: %1 (mit „Ins Modell übernehmen“ auf der Diagnoseseite hinzugefügt). Die obigen Fehler wurden mit ihnen identifiziert, und die kompensierten Sollwerte enthalten ihre Korrekturen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>RMS residual of the declared model alone: %1 µm.</source>
        <translation>RMS-Residuum des deklarierten Modells allein: %1 µm.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Path (XY)</source>
        <translation>Bahn (XY)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+288"/>
        <source>Radial deviation (polar, magnified)</source>
        <translation>Radiale Abweichung (polar, vergrößert)</translation>
    </message>
    <message>
        <location line="-272"/>
        <source>Compensation</source>
        <translation>Kompensation</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compensated references for the nominal circle (the commanded points of the test) from the identified errors (Eq. 15), and the largest |radial deviation| from the nominal circle before and after:</source>
        <translation>Kompensierte Sollwerte für den Nennkreis (die programmierten Punkte des Tests) aus den identifizierten Fehlern (Gl. 15) und die größte |radiale Abweichung| vom Nennkreis vorher und nachher:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>path</source>
        <translation>Bahn</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max. dev. (µm)</source>
        <translation>max. Abw. (µm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>measured, before compensation</source>
        <translation>gemessen, vor der Kompensation</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>after, through the simulated machine (true errors, noise free)</source>
        <translation>nachher, durch die simulierte Maschine (wahre Fehler, rauschfrei)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>after, expected from the measured residual (noise stays)</source>
        <translation>nachher, erwartet aus dem gemessenen Residuum (Rauschen bleibt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>after, through the identified model</source>
        <translation>nachher, durch das identifizierte Modell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest correction |reference − nominal|</source>
        <translation>größte Korrektur |Sollwert − Nennwert|</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Statistical process control</source>
        <translation>Statistische Prozessregelung</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+291"/>
        <source>The SPC series could not be charted: %1</source>
        <translation>Die SPC-Reihe konnte nicht dargestellt werden: %1</translation>
    </message>
    <message>
        <location line="-282"/>
        <source>Statistical process control of “%1” (%2)</source>
        <translation>Statistische Prozessregelung von „%1“ (%2)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Histogram of %1 (%2 values)</source>
        <translation>Histogramm von %1 (%2 Werte)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>index</source>
        <translation>Index</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../widgets/report/matchingsection.cpp" line="+437"/>
        <location filename="../widgets/report/summarysection.cpp" line="+157"/>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>subgroups × size</source>
        <translation>Untergruppen × Umfang</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A2 / D3 / D4</source>
        <translation>A2 / D3 / D4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>X-bar chart CL / UCL / LCL</source>
        <translation>x̄-Karte CL / UCL / LCL</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>R chart CL / UCL / LCL</source>
        <translation>R-Karte CL / UCL / LCL</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+151"/>
        <location line="+99"/>
        <source>in control</source>
        <translation>beherrscht</translation>
    </message>
    <message>
        <location line="-249"/>
        <source>Nelson rules (subgroups)</source>
        <translation>Nelson-Regeln (Stichproben)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>σ within (R̄ / d2)</source>
        <translation>σ innerhalb (R̄ / d2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>LSL / USL</source>
        <translation>LSL / USL</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cp (Eq. 16) / Cpk</source>
        <translation>Cp (Gl. 16) / Cpk</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>natural tolerance (Eq. 17)</source>
        <translation>natürliche Toleranz (Gl. 17)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>systematic error (Eq. 20)</source>
        <translation>systematischer Fehler (Gl. 20)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 ± %3 (%4)</source>
        <translation>%1%2 ± %3 (%4)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>significant</source>
        <translation>signifikant</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not significant</source>
        <translation>nicht signifikant</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>regression offset angle (Fig. 10)</source>
        <translation>Versatzwinkel der Regression (Abb. 10)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1° (slope %2%3 per sample, r² %4)</source>
        <translation>%1° (Steigung %2%3 je Probe, r² %4)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+128"/>
        <location line="+97"/>
        <source>SPC-gated compensation: %1</source>
        <translation>SPC-gesteuerte Kompensation: %1</translation>
    </message>
    <message>
        <location line="-218"/>
        <source>From the SPC offset angle to actuator errors</source>
        <translation>Vom SPC-Versatzwinkel zu den Antriebsfehlern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The actuator errors could not be derived from the edges: %1</source>
        <translation>Die Antriebsfehler konnten nicht aus den Kanten abgeleitet werden: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The regression line of the deviation of an edge machined along X against the measured position (%1, Fig. 10, Table 2) has the offset angle atan(slope); by Eq. 9 it is the X actuator&apos;s orientation error a, minus the offset angle of the edge along Y is b, and the two intercepts give the actuator origin (Table 3). A slope or intercept within ± %2 standard errors counts as scatter. The circular test&apos;s identification is an independent estimate of the same errors.</source>
        <translation>Die Regressionsgerade der Abweichung einer entlang X bearbeiteten Kante über der gemessenen Position (%1, Abb. 10, Tab. 2) hat den Versatzwinkel atan(Steigung); nach Gl. 9 ist er der Richtungsfehler a des X-Antriebs, der negative Versatzwinkel der Kante entlang Y ist b, und die beiden Achsenabschnitte ergeben den Ursprung der Antriebe (Tab. 3). Eine Steigung oder ein Achsenabschnitt innerhalb ± %2 Standardfehler gilt als Streuung. Die Identifikation aus dem Kreisformtest ist eine unabhängige Schätzung derselben Fehler.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>from SPC</source>
        <translation>aus SPC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>from circular test</source>
        <translation>aus Kreisformtest</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>offset angle, edge along X (deg)</source>
        <translation>Versatzwinkel, Kante entlang X (Grad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+4"/>
        <location line="+52"/>
        <source>%1 ± %2</source>
        <translation>%1 ± %2</translation>
    </message>
    <message>
        <location line="-53"/>
        <source>offset angle, edge along Y (deg)</source>
        <translation>Versatzwinkel, Kante entlang Y (Grad)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>systematic error, edge along X / Y (Eq. 20, µm)</source>
        <translation>systematischer Fehler, Kante entlang X / Y (Gl. 20, µm)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Compensation applied (Eq. 15): the largest correction of the nominal circle is %1 µm; the circular test&apos;s model gives a largest deviation of %2 µm before and %3 µm with the references derived from SPC.</source>
        <translation>Kompensation angewendet (Gl. 15): Die größte Korrektur des Nennkreises beträgt %1 µm; das Modell des Kreisformtests ergibt eine größte Abweichung von %2 µm vorher und %3 µm mit den aus SPC abgeleiteten Sollwerten.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not compensated: %1</source>
        <translation>Nicht kompensiert: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Three axes: circular tests in XY, YZ and ZX</source>
        <translation>Drei Achsen: Kreisformtests in XY, YZ und ZX</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The three-axis errors could not be identified: %1</source>
        <translation>Die Fehler der drei Achsen konnten nicht identifiziert werden: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The three-axis Cartesian model P = o + [i j k]·Pr (%1, Eq. 9 in three axes) fitted to the three tests together (%2 points, RMS residual %3 µm): origin (%4, %5, %6) µm. In every plane (u, v) the u actuator moves along (cos a, sin a), the v actuator along (−sin b, cos b); squareness b − a.</source>
        <translation>Das kartesische Dreiachsmodell P = o + [i j k]·Pr (%1, Gl. 9 für drei Achsen), gemeinsam an die drei Tests angepasst (%2 Punkte, RMS-Residuum %3 µm): Ursprung (%4; %5; %6) µm. In jeder Ebene (u, v) bewegt sich der u-Antrieb entlang (cos a, sin a), der v-Antrieb entlang (−sin b, cos b); Rechtwinkligkeit b − a.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>a (deg)</source>
        <translation>a (Grad)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>b (deg)</source>
        <translation>b (Grad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>squareness (deg)</source>
        <translation>Rechtwinkligkeit (Grad)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMS (µm)</source>
        <translation>RMS (µm)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Circular test %1: actuator origin offset (%2, %3) µm, squareness error %4°; largest radial deviation %5 µm.</source>
        <translation>Kreisformtest %1: Nullpunktversatz der Antriebe (%2; %3) µm, Rechtwinkligkeitsfehler %4°; größte radiale Abweichung %5 µm.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>compensated references (G-code)</source>
        <translation>kompensierte Sollwerte (G-Code)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up to %1 µm</source>
        <translation>bis %1 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>file %1 (Kinematics page, Export G-code)</source>
        <translation>Datei %1 (Seite Kinematik, G-Code exportieren)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest radial deviation %1 µm</source>
        <translation>größte radiale Abweichung %1 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 µm expected with the compensated references</source>
        <translation>%1 µm erwartet mit den kompensierten Sollwerten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The identified actuator errors explain the measured path; with the compensated references the largest radial deviation falls from %1 µm to about %2 µm (the measuring noise stays).</source>
        <translation>Die bestimmten Antriebsfehler erklären die gemessene Bahn; mit den kompensierten Sollwerten sinkt die größte radiale Abweichung von %1 µm auf etwa %2 µm (das Messrauschen bleibt).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Run the compensated references (%1) and repeat the circular test.</source>
        <translation>Fahren Sie die kompensierten Sollwerte (%1) und wiederholen Sie den Kreisformtest.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Do not compensate: the references would not reduce the deviation.</source>
        <translation>Nicht kompensieren: Die Sollwerte würden die Abweichung nicht verringern.</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+99"/>
        <source>SPC of %1: %2.</source>
        <translation>SPC von %1: %2.</translation>
    </message>
    <message>
        <location line="-96"/>
        <location line="+98"/>
        <source>out of control</source>
        <translation>außer Kontrolle</translation>
    </message>
    <message>
        <location line="-96"/>
        <location line="+98"/>
        <source>Cpk %1.</source>
        <translation>Cpk %1.</translation>
    </message>
    <message>
        <location line="-91"/>
        <source>From the SPC offset angles: origin (%1, %2) µm, squareness %3°.</source>
        <translation>Aus den SPC-Versatzwinkeln: Ursprung (%1; %2) µm, Rechtwinkligkeit %3°.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Squareness XY %1°, YZ %2°, ZX %3° (three-plane circular tests).</source>
        <translation>Rechtwinkligkeit XY %1°, YZ %2°, ZX %3° (Kreisformtests in drei Ebenen).</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 points of a radial-only circular test (angle and radial deviation, as ballbar software exports it); %2 loops. It has no commanded and measured x/y coordinates, so the actuator errors cannot be identified from it and no compensation is computed; its ISO 230-4 results follow.</source>
        <translation>%1 Punkte eines rein radialen Kreisformtests (Winkel und radiale Abweichung, wie Ballbar-Software sie exportiert); %2 Schleifen. Er hat keine Soll- und Ist-Koordinaten x/y, daher lassen sich die Antriebsfehler daraus nicht identifizieren und es wird keine Kompensation berechnet; es folgen seine Ergebnisse nach ISO 230-4.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Circular test %1 (radial only): largest circular deviation G %2 µm.</source>
        <translation>Kreisformtest %1 (nur radial): größte Kreisformabweichung G %2 µm.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Circular hysteresis H %1 µm.</source>
        <translation>Umkehrspanne H %1 µm.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The test gives the ISO 230-4 results only: a radial-only test cannot identify the actuator errors.</source>
        <translation>Der Test liefert nur die Ergebnisse nach ISO 230-4: ein rein radialer Test kann die Antriebsfehler nicht identifizieren.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>To identify and compensate the actuator errors, record the circular test with commanded and measured x/y coordinates.</source>
        <translation>Um die Antriebsfehler zu identifizieren und zu kompensieren, den Kreisformtest mit Soll- und Ist-Koordinaten x/y aufzeichnen.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The project has no circular test: the study charts its part series only; no actuator errors are identified and no compensation is computed.</source>
        <translation>Das Projekt hat keinen Kreisformtest: Die Studie zeigt nur ihre Teileserie; es werden keine Antriebsfehler identifiziert und keine Kompensation berechnet.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No SPC series is chosen.</source>
        <translation>Es ist keine SPC-Reihe gewählt.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Choose the series and its column on the Kinematics page, SPC tab.</source>
        <translation>Wählen Sie die Reihe und ihre Spalte auf der Seite Kinematik, Registerkarte SPC.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Keep charting the series; act when a point leaves the limits.</source>
        <translation>Die Reihe weiter aufzeichnen; eingreifen, wenn ein Punkt die Grenzen verlässt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Find the assignable cause of the out-of-control points before compensating.</source>
        <translation>Vor dem Kompensieren die zuordenbare Ursache der Punkte außerhalb der Regelgrenzen finden.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Kinematic compensation and SPC</source>
        <translation>Kinematische Kompensation und SPC</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Cannot analyse the circular test: %1</source>
        <translation>Der Kreisformtest kann nicht ausgewertet werden: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The circular test could not be analysed: %1</source>
        <translation>Der Kreisformtest konnte nicht ausgewertet werden: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Repeat the circular test and check its file.</source>
        <translation>Wiederholen Sie den Kreisformtest und prüfen Sie seine Datei.</translation>
    </message>
    <message>
        <location filename="../widgets/report/matchingsection.cpp" line="-390"/>
        <source>SADE (paper settings)</source>
        <translation>SADE (Originalparameter)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GA-simplex</source>
        <translation>GA-Simplex</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>closed form (LS optimum)</source>
        <translation>geschlossene Form (LS-Optimum)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>minimax</source>
        <translation>Minimax</translation>
    </message>
    <message>
        <location line="+215"/>
        <source>Probe points “%1”, tolerance ±%2 mm</source>
        <translation>Antastpunkte „%1“, Toleranz ±%2 mm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Closed form and minimax were run on the %1 points, each re-projected onto the CAD part at every posture until the posture stopped changing. The posture after matching is that of %2; the machine adjustment values are for the study&apos;s %3 machine. Deviation: along the part&apos;s normal at the closest point.</source>
        <translation>Geschlossene Lösung und Minimax wurden auf die %1 Punkte angewandt, jeder bei jeder Lage neu auf das CAD-Teil projiziert, bis sich die Lage nicht mehr änderte. Die Lage nach dem Einpassen ist die von %2; die Maschinenstellwerte gelten für die %3-Maschine der Studie. Abweichung: entlang der Teilenormalen im nächsten Punkt.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Every method was run on the %1 points (%2). The posture after matching is that of %3; the machine adjustment values are for the study&apos;s %4 machine. Deviation: %5. Rough matching, SADE, GA-simplex and the machine adjustment as in %6.</source>
        <translation>Jedes Verfahren lief auf den %1 Punkten (%2). Die Lage nach dem Einpassen ist die von %3; die Maschinenkorrekturwerte gelten für die Maschine %4 der Studie. Abweichung: %5. Grobeinpassung, SADE, GA-Simplex und Maschinenkorrektur wie in %6.</translation>
    </message>
    <message>
        <location line="+5"/>
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
        <source>along the nominal normal</source>
        <translation>entlang der Nennnormalen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance |p − (sRq + t)|</source>
        <translation>Abstand |p − (sRq + t)|</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Includes applied effects: %1 (diagnosis, Apply). The nominal points were deformed by them before matching, so the deviations and the machine adjustments below are those of the model with these effects.</source>
        <translation>Enthält übernommene Effekte: %1 (Diagnose, Übernehmen). Die Nennpunkte wurden vor der Ausrichtung durch sie verformt; die Abweichungen und Maschineneinstellungen unten gelten daher für das Modell mit diesen Effekten.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Before matching</source>
        <translation>Vor der Ausrichtung</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+6"/>
        <source>%1 of %2 out of ±%3 mm, max |d| %4 mm</source>
        <translation>%1 von %2 außerhalb ±%3 mm, max |d| %4 mm</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>After %1</source>
        <translation>Nach %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1; grey: nominal points; lines: deviation vectors ×%2 (both views); large outlined points: out of tolerance.</source>
        <translation>%1; grau: Nennpunkte; Linien: Abweichungsvektoren ×%2 (beide Ansichten); große umrandete Punkte: außerhalb der Toleranz.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Top view</source>
        <translation>Draufsicht</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Oblique view as in the program</source>
        <translation>Schrägansicht wie im Programm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The nominal is the CAD part “%1” (%2 triangles): the points were matched to its surface, re-projected at each posture. The part is coloured as the nearest probed point, light grey where none is near.</source>
        <translation>Der Sollwert ist das CAD-Teil „%1“ (%2 Dreiecke): die Punkte wurden an seine Oberfläche angepasst, bei jeder Lage neu projiziert. Das Teil ist wie der nächste Antastpunkt gefärbt, hellgrau, wo keiner nahe ist.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>before: deviation (mm), green = within ±%1</source>
        <translation>vorher: Abweichung (mm), grün = innerhalb ±%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>after: deviation (mm), green = within ±%1</source>
        <translation>nachher: Abweichung (mm), grün = innerhalb ±%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../widgets/report/probesection.cpp" line="+315"/>
        <source>surface</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../widgets/report/probesection.cpp" line="-39"/>
        <location line="+39"/>
        <source>points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMSE before</source>
        <translation>RMSE vorher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max before</source>
        <translation>max vorher</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out before</source>
        <translation>außerhalb vorher</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMSE after</source>
        <translation>RMSE nachher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max after</source>
        <translation>max nachher</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out after</source>
        <translation>außerhalb nachher</translation>
    </message>
    <message>
        <location line="+12"/>
        <location filename="../widgets/report/probesection.cpp" line="+13"/>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Deviations before and after %1 (mm)</source>
        <translation>Abweichungen vor und nach %1 (mm)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../widgets/report/setupsection.cpp" line="+210"/>
        <source>method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rx, ry, rz (deg)</source>
        <translation>rx, ry, rz (Grad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>x, y, z (mm)</source>
        <translation>x, y, z (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMSE</source>
        <translation>RMSE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max |d|</source>
        <translation>max |d|</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out</source>
        <translation>außerhalb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>evals</source>
        <translation>Auswert.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>rough</source>
        <translation>grob</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Methods (RMSE and max |d| in mm)</source>
        <translation>Methoden (RMSE und max |d| in mm)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Locked: %1. The rough stage&apos;s three-point frames cannot hold a lock; its angles are only the start the fine stage moves to the lock values.</source>
        <translation>Gesperrt: %1. Die Dreipunkt-Koordinatensysteme der Grobausrichtung können keine Sperre halten; ihre Winkel sind nur der Start, den die Feinausrichtung auf die Sperrwerte bringt.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+127"/>
        <source>frame rotation</source>
        <translation>Drehung des Koordinatensystems</translation>
    </message>
    <message>
        <location line="-126"/>
        <source>Machine adjustment values (%1%2)</source>
        <translation>Maschineneinstellwerte (%1%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, OUTSIDE TRAVEL</source>
        <translation>, AUSSERHALB DES VERFAHRWEGS</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>control</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>blocks (mm, °)</source>
        <translation>Sätze (mm, °)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (the study&apos;s control)</source>
        <translation>%1 (die Steuerung der Studie)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The same posture as a controller frame (instead of the axis values; decimals: %1)</source>
        <translation>Dieselbe Lage als Steuerungs-Frame (statt der Achswerte; Nachkommastellen: %1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Datum shift then rotation of the working plane; no axis moves (STAY). The whole programs: metrofit-cli match --frame heidenhain|siemens|fanuc.</source>
        <translation>Nullpunktverschiebung, dann Schwenken der Bearbeitungsebene; keine Achse fährt (STAY). Die vollständigen Programme: metrofit-cli match --frame heidenhain|siemens|fanuc.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>round</source>
        <translation>Runde</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max |d| (mm)</source>
        <translation>max |d| (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out of tol.</source>
        <translation>außer Tol.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SX, SY, SZ (mm)</source>
        <translation>SX, SY, SZ (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S%1, S%2 (deg)</source>
        <translation>S%1, S%2 (Grad)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>in tolerance</source>
        <translation>in Toleranz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Remeasure loop (simulated machine and CMM)</source>
        <translation>Nachmessschleife (simulierte Maschine und KMG)</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>Every point within tolerance after %n adjustment(s).</source>
        <translation>
            <numerusform>Jeder Punkt nach %n Korrektur innerhalb der Toleranz.</numerusform>
            <numerusform>Jeder Punkt nach %n Korrekturen innerhalb der Toleranz.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>FAILED: the best fit leaves points out of tolerance (form error larger than the tolerance); no WCS adjustment can bring them in.</source>
        <translation>FEHLGESCHLAGEN: Die beste Einpassung lässt Punkte außerhalb der Toleranz (Formfehler größer als die Toleranz); keine Verschiebung des Werkstückkoordinatensystems bringt sie hinein.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>FAILED: the adjustment is beyond the machine&apos;s travel; the WCS was not moved.</source>
        <translation>FEHLGESCHLAGEN: Die Korrektur liegt außerhalb des Verfahrwegs der Maschine; das Werkstückkoordinatensystem wurde nicht verschoben.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>FAILED: still out of tolerance after the last adjustment.</source>
        <translation>FEHLGESCHLAGEN: Nach der letzten Korrektur noch außerhalb der Toleranz.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stopped before the end.</source>
        <translation>Vor dem Ende angehalten.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>True remaining error of the simulated part: %1 mm at most, %2 point(s) out of tolerance.</source>
        <translation>Wahrer Restfehler des simulierten Teils: höchstens %1 mm, %2 Punkt(e) außerhalb der Toleranz.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The workpiece %1 sits rotated by (%2, %3, %4)° and shifted by (%5, %6, %7) mm; %8 of %9 probed points are out of ±%10 mm before matching, %11 after.</source>
        <translation>Das Werkstück %1 liegt um (%2; %3; %4)° gedreht und um (%5; %6; %7) mm verschoben; %8 von %9 angetasteten Punkten liegen vor dem Einpassen außerhalb ±%10 mm, danach %11.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 machine, enter at the control</source>
        <translation>Maschine %1, an der Steuerung eingeben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linear axes</source>
        <translation>Linearachsen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rotary axes</source>
        <translation>Rundachsen</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+4"/>
        <source>max |deviation| %1 mm; %2 of %3 points out of tolerance</source>
        <translation>max. |Abweichung| %1 mm; %2 von %3 Punkten außerhalb der Toleranz</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>After the posture adjustment every probed point lies within the tolerance.</source>
        <translation>Nach der Lagekorrektur liegt jeder angetastete Punkt innerhalb der Toleranz.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Even after the best posture %1 of %2 points stay out of tolerance: the part itself deviates, not only its posture.</source>
        <translation>Selbst in der besten Lage bleiben %1 von %2 Punkten außerhalb der Toleranz: Das Teil selbst weicht ab, nicht nur seine Lage.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Do not apply: the adjustment lies outside the axis travel (%1).</source>
        <translation>Nicht anwenden: Die Korrektur liegt außerhalb des Verfahrbereichs (%1).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Enter the adjustment values at the control, probe the part again and machine when it is within tolerance.</source>
        <translation>Geben Sie die Korrekturwerte an der Steuerung ein, tasten Sie das Teil erneut an und bearbeiten Sie es, wenn es in der Toleranz liegt.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Enter the adjustment values, probe again, and check the surfaces that stay out of tolerance before machining.</source>
        <translation>Geben Sie die Korrekturwerte ein, tasten Sie erneut an und prüfen Sie vor der Bearbeitung die Flächen, die außerhalb der Toleranz bleiben.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Posture matching — before and after</source>
        <translation>Lageausrichtung — vorher und nachher</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The matching study&apos;s probe points could not be found.</source>
        <translation>Die Antastpunkte der Ausrichtungsstudie wurden nicht gefunden.</translation>
    </message>
    <message>
        <location filename="../widgets/report/probesection.cpp" line="-256"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location line="+123"/>
        <location line="+5"/>
        <source>%1 (mm)</source>
        <translation>%1 (mm)</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>Probe points “%1”</source>
        <translation>Antastpunkte „%1“</translation>
    </message>
    <message>
        <location line="+21"/>
        <location filename="../widgets/report/setupsection.cpp" line="-96"/>
        <location line="+43"/>
        <location filename="../widgets/report/summarysection.cpp" line="+123"/>
        <location filename="../widgets/report/thermalsection.cpp" line="-284"/>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>surfaces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deviation</source>
        <translation>Abweichung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>along the nominal normal, before matching</source>
        <translation>entlang der Nennnormalen, vor der Ausrichtung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance |p − q| (no normals), before matching</source>
        <translation>Abstand |p − q| (ohne Normalen), vor der Ausrichtung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean |deviation|</source>
        <translation>mittlere |Abweichung|</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMS deviation</source>
        <translation>RMS-Abweichung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max |deviation|</source>
        <translation>max |Abweichung|</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (point %2)</source>
        <translation>%1 (Punkt %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+29"/>
        <source>outside ±%1 mm</source>
        <translation>außerhalb ±%1 mm</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>mean deviation</source>
        <translation>mittlere Abweichung</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+5"/>
        <source>Top view (XY)</source>
        <translation>Draufsicht (XY)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Front view (XZ)</source>
        <translation>Vorderansicht (XZ)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>deviation along the normal (mm)</source>
        <translation>Abweichung entlang der Normalen (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance |p − q| (mm)</source>
        <translation>Abstand |p − q| (mm)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>mean deviation (mm)</source>
        <translation>mittlere Abweichung (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mean distance (mm)</source>
        <translation>mittlerer Abstand (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max |deviation| (mm)</source>
        <translation>max |Abweichung| (mm)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Posture matching — probe points</source>
        <translation>Lageausrichtung — Antastpunkte</translation>
    </message>
    <message>
        <location filename="../widgets/report/summarysection.cpp" line="-147"/>
        <source>Metrofit report</source>
        <translation>Metrofit-Bericht</translation>
    </message>
    <message>
        <location filename="../widgets/report/setupsection.cpp" line="+83"/>
        <location filename="../widgets/report/summarysection.cpp" line="+146"/>
        <source>kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../widgets/report/summarysection.cpp" line="-229"/>
        <source>thermal log</source>
        <translation>Thermo-Protokoll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>probed points</source>
        <translation>angetastete Punkte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>circular test</source>
        <translation>Kreisformtest</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CMM report</source>
        <translation>KMG-Protokoll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setup model</source>
        <translation>Einrichtemodell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feature series</source>
        <translation>Merkmalsreihe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DMIS output</source>
        <translation>DMIS-Ausgabe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Q-DAS DFQ file</source>
        <translation>Q-DAS-DFQ-Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zeiss Calypso table</source>
        <translation>Zeiss-Calypso-Tabelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>QIF results</source>
        <translation>QIF-Ergebnisse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MTConnect log</source>
        <translation>MTConnect-Protokoll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAD part</source>
        <translation>CAD-Teil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hole table</source>
        <translation>Bohrungstabelle</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>none given</source>
        <translation>nicht angegeben</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Conclusion</source>
        <translation>Fazit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Recommendation: %1</source>
        <translation>Empfehlung: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Project “%1”, report made %2 by Metrofit version %3. The project&apos;s description and every dataset&apos;s origin are in the appendix.</source>
        <translation>Projekt „%1“, Bericht erstellt %2 mit Metrofit Version %3. Die Beschreibung des Projekts und die Herkunft jedes Datensatzes stehen im Anhang.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>What each study found</source>
        <translation>Was jede Studie ergab</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+9"/>
        <location line="+21"/>
        <location line="+14"/>
        <location line="+99"/>
        <source>study</source>
        <translation>Studie</translation>
    </message>
    <message>
        <location line="-143"/>
        <location line="+44"/>
        <source>found</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>recommendation</source>
        <translation>Empfehlung</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>change</source>
        <translation>Änderung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where</source>
        <translation>wo</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>What to change on the machine</source>
        <translation>Was an der Maschine zu ändern ist</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing: no study proposes a change.</source>
        <translation>Nichts: Keine Studie schlägt eine Änderung vor.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>error before</source>
        <translation>Fehler vorher</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>error after</source>
        <translation>Fehler nachher</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Error before and after</source>
        <translation>Fehler vorher und nachher</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What the closed loop found and leaves unexplained</source>
        <translation>Was der geschlossene Regelkreis fand und unerklärt lässt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>error before → after</source>
        <translation>Fehler vorher → nachher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>still unexplained</source>
        <translation>noch unerklärt</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>What was measured</source>
        <translation>Was gemessen wurde</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 (%2, %3 rows)</source>
        <translation>%1 (%2, %3 Zeilen)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+11"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1. Files dated %2. Licences: %3.</source>
        <translation>%1. Dateien vom %2. Lizenzen: %3.</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n further dataset(s) of the project are used by no study.</source>
        <translation>
            <numerusform>%n weiterer Datensatz des Projekts wird von keiner Studie verwendet.</numerusform>
            <numerusform>%n weitere Datensätze des Projekts werden von keiner Studie verwendet.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The project declares no study a section of this report could show yet.</source>
        <translation>Das Projekt deklariert noch keine Studie, die ein Abschnitt dieses Berichts zeigen könnte.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1, page %2</source>
        <translation>%1, Seite %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Contents: %1.</source>
        <translation>Inhalt: %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>References</source>
        <translation>Literatur</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Appendix: data provenance</source>
        <translation>Anhang: Herkunft der Daten</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Every dataset of the project, where it comes from and under which licence; file names are relative to the project&apos;s folder.</source>
        <translation>Jeder Datensatz des Projekts, woher er stammt und unter welcher Lizenz; Dateinamen relativ zum Projektordner.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>rows / points</source>
        <translation>Zeilen / Punkte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>file date</source>
        <translation>Dateidatum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>licence</source>
        <translation>Lizenz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Study settings</source>
        <translation>Einstellungen der Studien</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>settings as the project file holds them</source>
        <translation>Einstellungen wie in der Projektdatei</translation>
    </message>
    <message>
        <location line="-71"/>
        <source>The project references no datasets.</source>
        <translation>Das Projekt verweist auf keine Datensätze.</translation>
    </message>
    <message>
        <location filename="../widgets/report/report.cpp" line="+128"/>
        <location filename="../widgets/report/reportpainter.cpp" line="+108"/>
        <source>Metrofit %1</source>
        <translation>Metrofit %1</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../widgets/report/reportpainter.cpp" line="+22"/>
        <source>page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>page %1</source>
        <translation>Seite %1</translation>
    </message>
    <message>
        <location filename="../widgets/report/setupsection.cpp" line="-190"/>
        <source>machine point</source>
        <translation>Maschinenpunkt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work offset</source>
        <translation>Nullpunktverschiebung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tool length</source>
        <translation>Werkzeuglänge</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Setup-data correction</source>
        <translation>Einrichtdatenkorrektur</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Model “%1”</source>
        <translation>Modell „%1“</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setup data</source>
        <translation>Einrichtdaten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1: %2 work offsets, %3 tools, %4 machine points</source>
        <translation>%1: %2 Nullpunktverschiebungen, %3 Werkzeuge, %4 Maschinenpunkte</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>features</source>
        <translation>Formelemente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dimensions</source>
        <translation>Maße</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arcs</source>
        <translation>Kanten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decision space</source>
        <translation>Entscheidungsraum</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>axis %1, grid %2 mm, bounds [%3, %4] mm</source>
        <translation>Achse %1, Raster %2 mm, Grenzen [%3; %4] mm</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The project has no CMM report for this model: nothing to correct.</source>
        <translation>Das Projekt hat keinen KMG-Messbericht für dieses Modell: nichts zu korrigieren.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Report data “%1”</source>
        <translation>Berichtsdaten „%1“</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>parts</source>
        <translation>Werkstücke</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../widgets/report/thermalsection.cpp" line="+1"/>
        <location line="+184"/>
        <source>rows</source>
        <translation>Zeilen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (deviation of a dimension: mean over its rows)</source>
        <translation>%1 (Abweichung eines Maßes: Mittelwert über seine Zeilen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>before correction</source>
        <translation>vor der Korrektur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>f1 = %1 mm; %2 of %3 mean deviations out of tolerance</source>
        <translation>f1 = %1 mm; %2 von %3 mittleren Abweichungen außerhalb der Toleranz</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (deviation of a dimension: predicted for part %2)</source>
        <translation>%1 (Abweichung eines Maßes: vorhergesagt für Werkstück %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>applied effects</source>
        <translation>übernommene Effekte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (diagnosis, Apply)</source>
        <translation>%1 (Diagnose, Übernehmen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>model residual</source>
        <translation>Modellresiduum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms %1 mm (declared model %2 mm)</source>
        <translation>rms %1 mm (deklariertes Modell %2 mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>last part predicted</source>
        <translation>Vorhersage des letzten Werkstücks</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms %1 mm from the other parts (declared model %2 mm)</source>
        <translation>rms %1 mm aus den übrigen Werkstücken (deklariertes Modell %2 mm)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Objectives as in %4, Eq. 6–10: f1 = the smallest unilateral error budget over all dimensions after correction (maximised), f2 = |x| (minimised among the f1-optimal), f = 10 f1 − f2. Exact: LP / MILP on the %1 mm grid (GLPK), then the least-norm correction. CRIPSO: 100 polyps, w = 0.75, c1 = c2 = cos(π/2 Li/L); PSO: 100 particles, asynchronous gbest, same coefficients. Budget %2 solutions, seed %3.</source>
        <translation>Zielfunktionen wie in %4, Gl. 6–10: f1 = das kleinste einseitige Fehlerbudget über alle Maße nach der Korrektur (maximiert), f2 = |x| (minimiert unter den f1-optimalen), f = 10 f1 − f2. Exakt: LP / MILP auf dem %1-mm-Raster (GLPK), dann die Korrektur kleinster Norm. CRIPSO: 100 Polypen, w = 0,75, c1 = c2 = cos(π/2 Li/L); PSO: 100 Partikel, asynchrones gbest, gleiche Koeffizienten. Budget %2 Lösungen, Startwert %3.</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Error in the setup model of the study %1: %2</source>
        <translation>Fehler im Setup-Modell der Studie %1: %2</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>The exact correction of %1 setup data raises the smallest error budget f1 from %2 mm to %3 mm%4; CRIPSO and PSO reach %5 mm and %6 mm.</source>
        <translation>Die exakte Korrektur von %1 Einrichtedaten hebt das kleinste Fehlerbudget f1 von %2 mm auf %3 mm%4; CRIPSO und PSO erreichen %5 mm und %6 mm.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> (proven optimal)</source>
        <translation> (nachweislich optimal)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>work offsets</source>
        <translation>Nullpunktverschiebungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tool lengths</source>
        <translation>Werkzeuglängen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine points</source>
        <translation>Maschinenpunkte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>add along %1; file %2 (program O7001)</source>
        <translation>entlang %1 addieren; Datei %2 (Programm O7001)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+4"/>
        <source>f1 %1 mm; %2 of %3 dimensions out of tolerance</source>
        <translation>f1 %1 mm; %2 von %3 Maßen außerhalb der Toleranz</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The correction widens the smallest margin to the tolerance limits by %1 mm; %2 of %3 dimensions stay out of tolerance.</source>
        <translation>Die Korrektur vergrößert den kleinsten Abstand zu den Toleranzgrenzen um %1 mm; %2 von %3 Maßen bleiben außerhalb der Toleranz.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No correction widens the smallest margin: the registers are as good as the measurements allow.</source>
        <translation>Keine Korrektur vergrößert den kleinsten Abstand: Die Register sind so gut, wie es die Messungen erlauben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Add the exact corrections to the offset registers (%1, Setup page, Export; Heidenhain and Siemens formats there too), then measure the next part.</source>
        <translation>Addieren Sie die exakten Korrekturen zu den Korrekturregistern (%1, Seite Einrichten, Exportieren; dort auch Heidenhain- und Siemens-Format) und messen Sie dann das nächste Teil.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Leave the offset registers as they are.</source>
        <translation>Lassen Sie die Korrekturregister unverändert.</translation>
    </message>
    <message>
        <location line="-157"/>
        <source>Convergence</source>
        <translation>Konvergenz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Comparison</source>
        <translation>Vergleich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>f1 (mm)</source>
        <translation>f1 (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>f2 (mm)</source>
        <translation>f2 (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f</source>
        <translation>f</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bonus (mm)</source>
        <translation>Bonus (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>gap f1 (mm)</source>
        <translation>Abstand f1 (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solutions</source>
        <translation>Lösungen</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Exact certificate: f1 %1 on the grid, |x| %2 among the f1-optimal corrections (%3 LP / MILP solver calls). Gap f1: the exact f1 minus the method&apos;s.</source>
        <translation>Exakter Nachweis: f1 %1 auf dem Raster, |x| %2 unter den f1-optimalen Korrekturen (%3 LP-/MILP-Solver-Aufrufe). Abstand f1: das exakte f1 minus das der Methode.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>proven optimal</source>
        <translation>nachweislich optimal</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NOT proven optimal</source>
        <translation>NICHT nachweislich optimal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>proven minimal</source>
        <translation>nachweislich minimal</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not proven minimal</source>
        <translation>nicht nachweislich minimal</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Corrections (mm, to add to the registers along %1)</source>
        <translation>Korrekturen (mm, entlang %1 zu den Registern zu addieren)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>setup datum</source>
        <translation>Einrichtdatum</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>register</source>
        <translation>Register</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exact</source>
        <translation>exakt</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Margins per dimension, before and after the exact correction</source>
        <translation>Abstände je Maß, vor und nach der exakten Korrektur</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Export for the controller (Fanuc, exact corrections)</source>
        <translation>Export für die Steuerung (Fanuc, exakte Korrekturen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>metrofit-cli setup --export fanuc writes the same text; Heidenhain, Siemens and CSV are the other formats (see the sign convention in the header).</source>
        <translation>metrofit-cli setup --export fanuc schreibt denselben Text; Heidenhain, Siemens und CSV sind die weiteren Formate (siehe die Vorzeichenkonvention im Kopf).</translation>
    </message>
    <message>
        <location filename="../widgets/report/thermalsection.cpp" line="-271"/>
        <source>%1 h</source>
        <translation>%1 h</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+23"/>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message numerus="yes">
        <location line="+11"/>
        <source>%n temperature(s)</source>
        <translation>
            <numerusform>%n Temperatur</numerusform>
            <numerusform>%n Temperaturen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n displacement(s)</source>
        <translation>
            <numerusform>%n Verlagerung</numerusform>
            <numerusform>%n Verlagerungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n strain(s)</source>
        <translation>
            <numerusform>%n Dehnung</numerusform>
            <numerusform>%n Dehnungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n speed(s)</source>
        <translation>
            <numerusform>%n Drehzahl</numerusform>
            <numerusform>%n Drehzahlen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n other</source>
        <translation>
            <numerusform>%n sonstiger</numerusform>
            <numerusform>%n sonstige</numerusform>
        </translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 heating, %2 cooling, from the speed channel %3 (running = heating)</source>
        <translation>%1 Erwärmung, %2 Abkühlung, aus dem Drehzahlkanal %3 (läuft = Erwärmung)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 heating, %2 cooling, from the slope of the mean temperature</source>
        <translation>%1 Erwärmung, %2 Abkühlung, aus der Steigung der mittleren Temperatur</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>none detected</source>
        <translation>keine erkannt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Thermal log “%1”</source>
        <translation>Thermoprotokoll „%1“</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1, every %2 (median), time column %3</source>
        <translation>%1, alle %2 (Median), Zeitspalte %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>channels</source>
        <translation>Kanäle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phases</source>
        <translation>Phasen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chart</source>
        <translation>Diagramm</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 of %2 channels shown; the table lists all</source>
        <translation>%1 von %2 Kanälen angezeigt; die Tabelle listet alle</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>quantity</source>
        <translation>Größe</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>in chart</source>
        <translation>im Diagramm</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1 → %2%3</source>
        <translation>%1 → %2%3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>used by %1 (held-out error %2)</source>
        <translation>verwendet von %1 (Fehler auf den Testdaten %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not used by %1 (held-out error would rise: %2)</source>
        <translation>nicht verwendet von %1 (Fehler auf den Testdaten würde steigen: %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not used by %1 (held-out error would not fall: %2)</source>
        <translation>nicht verwendet von %1 (Fehler auf den Testdaten würde nicht sinken: %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Applied effects %1 (added with Apply on the diagnosis page; each model is fitted with and without them and keeps the lower held-out error): %2.</source>
        <translation>Übernommene Effekte %1 (mit „Ins Modell übernehmen“ auf der Diagnoseseite hinzugefügt; jedes Modell wird mit und ohne sie angepasst und behält den kleineren Fehler auf den Testdaten): %2.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Hysteresis</source>
        <translation>Hysterese</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No hysteresis analysis: %1</source>
        <translation>Keine Hystereseanalyse: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 against each sensor (Fig. 9 of %5): heating runs (the change of %1 grows, %2 rows) and cooling runs (%3 rows) in the colours of the trend chart&apos;s phases. Loop area by the shoelace formula; lag: the time constant of a first-order lag between sensor and displacement (&gt; 0: the sensor lags).%4</source>
        <translation>%1 über jedem Sensor (Abb. 9 in %5): Aufheizabschnitte (die Änderung von %1 wächst, %2 Zeilen) und Abkühlabschnitte (%3 Zeilen) in den Farben der Phasen des Verlaufsdiagramms. Schleifenfläche nach der Gaußschen Trapezformel; Verzögerung: die Zeitkonstante eines Verzögerungsglieds erster Ordnung zwischen Sensor und Verlagerung (&gt; 0: der Sensor eilt nach).%4</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Every row of the log is fitted, as on the Thermal page (trained there %1, stored in the project with these settings and this data), so the report chooses the page&apos;s model with the page&apos;s figures.</source>
        <translation>Jede Zeile des Protokolls wird angepasst, wie auf der Seite Thermik (dort trainiert %1, im Projekt mit diesen Einstellungen und diesen Daten gespeichert); der Bericht wählt daher das Modell der Seite mit deren Kennzahlen.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>To keep the report&apos;s run time short, this %1-row log is fitted on every %2th row (%3 rows); the GUI and metrofit-cli fit all rows and may choose another model. Train the models on the Thermal page and save the project: the report then fits every row and shows the page&apos;s choice.</source>
        <translation>Um die Laufzeit des Berichts kurz zu halten, wird dieses Protokoll mit %1 Zeilen an jeder %2. Zeile angepasst (%3 Zeilen); die GUI und metrofit-cli passen alle Zeilen an und können ein anderes Modell wählen. Trainieren Sie die Modelle auf der Seite Thermik und speichern Sie das Projekt: der Bericht passt dann jede Zeile an und zeigt die Wahl der Seite.</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>not fitted: %1</source>
        <translation>nicht angepasst: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: not fitted</source>
        <translation>%1: nicht angepasst</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Performance indices (Table 4 of %1): R correlation, RMSE, E Nash-Sutcliffe efficiency, band = largest |residual|. A model is usable for compensation only when on the held-out rows it does not diverge (RMSE at most %2 × the largest error), E ≥ %3 and R ≥ %4.</source>
        <translation>Gütemaße (Tabelle 4 in %1): R Korrelation, RMSE, E Nash-Sutcliffe-Effizienz, Band = größtes |Residuum|. Ein Modell taugt zur Kompensation nur, wenn es auf den zurückgehaltenen Zeilen nicht divergiert (RMSE höchstens %2 × der größte Fehler), E ≥ %3 und R ≥ %4.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Modular models (%1, Section 4.3)</source>
        <translation>Modulare Modelle (%1, Abschnitt 4.3)</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>not fitted</source>
        <translation>nicht angepasst</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 not fitted: %2.</source>
        <translation>%1 nicht angepasst: %2.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>modules, summed (distributed lag)</source>
        <translation>Module, summiert (verteilte Verzögerung)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 with inputs %2, up to %3 %4</source>
        <translation>%1 mit den Eingängen %2, bis zu %3 %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> (identified again on %1)</source>
        <translation> (erneut identifiziert an %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Module by module (the last row and the dotted curves): each module is identified on its own test alone, with the channels its own heating moves at least twice as much as the other test&apos;s, by the distributed-lag model, and the combined test is predicted as the sum of the modules, so that one module can be identified again without the others: %1.</source>
        <translation>Modul für Modul (die letzte Zeile und die gepunkteten Kurven): Jedes Modul wird allein an seinem eigenen Test identifiziert, mit den Kanälen, die seine eigene Erwärmung mindestens doppelt so stark bewegt wie der andere Test, durch das Modell mit verteilter Verzögerung, und der kombinierte Test wird als Summe der Module vorhergesagt, sodass ein Modul ohne die anderen neu identifiziert werden kann: %1.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Module by module: not identified (%1).</source>
        <translation>Modul für Modul: nicht identifiziert (%1).</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The thermal models could not be fitted: %1</source>
        <translation>Die thermischen Modelle konnten nicht angepasst werden: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Check the thermal study&apos;s target and inputs against the log.</source>
        <translation>Prüfen Sie Zielgröße und Eingänge der thermischen Studie am Protokoll.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 could not be fitted (%2)</source>
        <translation>%1 konnte nicht angepasst werden (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is not usable (%2)</source>
        <translation>%1 ist nicht verwendbar (%2)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 varies by RMS %2%3 (peak %4%3) on the held-out rows</source>
        <translation>%1 schwankt auf den zurückgehaltenen Zeilen um RMS %2%3 (Spitze %4%3)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Best usable model of %1: %2, held-out RMSE %3%4, residual band ±%5%4.</source>
        <translation>Bestes verwendbares Modell für %1: %2, RMSE zurückgehalten %3%4, Residuenband ±%5%4.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RMS %1%2 (band ±%3%2) left with %4</source>
        <translation>RMS %1%2 (Band ±%3%2) verbleibt mit %4</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>thermal compensation of %1</source>
        <translation>thermische Kompensation von %1</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>model fitted on %1; a grey model has no form a control runs: fit linear, lag or dlag to export it</source>
        <translation>an %1 angepasstes Modell; ein Grey-Modell hat keine Form, die eine Steuerung ausführt: für den Export linear, lag oder dlag anpassen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>model fitted on %1; export it for the control on the Thermal page (Export compensation) or with metrofit-cli thermal export --format %2</source>
        <translation>an %1 angepasstes Modell; für die Steuerung exportieren auf der Seite Thermik (Kompensation exportieren) oder mit metrofit-cli thermal export --format %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 predicts %2 on rows it was not fitted on to RMS %3%4, from RMS %5%4 without compensation.</source>
        <translation>%1 sagt %2 auf nicht angepassten Zeilen auf RMS %3%4 genau voraus, gegenüber RMS %5%4 ohne Kompensation.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Compensate %1 with %2; do not use the models marked not usable.</source>
        <translation>Kompensieren Sie %1 mit %2; verwenden Sie die als nicht verwendbar markierten Modelle nicht.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No model of %1 passes the held-out test.</source>
        <translation>Kein Modell für %1 besteht den Test auf den zurückgehaltenen Zeilen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Do not compensate with these models. Record a longer test covering heating and cooling, add sensors near the heat sources, and use the closed loop (diagnosis) to find the lag or inputs the model lacks.</source>
        <translation>Kompensieren Sie nicht mit diesen Modellen. Zeichnen Sie einen längeren Test mit Aufheizen und Abkühlen auf, setzen Sie Sensoren nahe den Wärmequellen und suchen Sie mit dem geschlossenen Regelkreis (Diagnose) die Verzögerung oder Eingänge, die dem Modell fehlen.</translation>
    </message>
    <message>
        <location line="-339"/>
        <source>Charts of the first %1 of %2 sensors; the table lists all.</source>
        <translation>Diagramme der ersten %1 von %2 Sensoren; die Tabelle listet alle.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>sensor</source>
        <translation>Sensor</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>loop area</source>
        <translation>Schleifenfläche</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>loop / ranges</source>
        <translation>Schleife / Spannweiten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lag τ (min)</source>
        <translation>Verzug τ (min)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R² with lag</source>
        <translation>R² mit Verzug</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R² static</source>
        <translation>R² statisch</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Thermal error models</source>
        <translation>Modelle des thermischen Fehlers</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>GNNMCI(1,N) (PSO, 90 particles, 100 iterations, seed %1), GMC(1,N) (least squares) and the MLP (%2-10-1, Levenberg-Marquardt, seed %1) predict %3 from %4; each is fitted on the first %5 % of the rows and tested on the rest (held out, shaded).</source>
        <translation>GNNMCI(1,N) (PSO, 90 Partikel, 100 Iterationen, Startwert %1), GMC(1,N) (kleinste Quadrate) und das MLP (%2-10-1, Levenberg-Marquardt, Startwert %1) sagen %3 aus %4 vorher; jedes wird an den ersten %5 % der Zeilen angepasst und am Rest getestet (Testdaten, schattiert).</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>The models could not be fitted: %1</source>
        <translation>Die Modelle konnten nicht angepasst werden: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>residual = measured − model</source>
        <translation>Residuum = gemessen − Modell</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+98"/>
        <source>model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <location line="-97"/>
        <location line="+103"/>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <location line="-103"/>
        <location line="+101"/>
        <source>RMSE (%1)</source>
        <translation>RMSE (%1)</translation>
    </message>
    <message>
        <location line="-100"/>
        <location line="+103"/>
        <source>E</source>
        <translation>E</translation>
    </message>
    <message>
        <location line="-103"/>
        <location line="+98"/>
        <source>band (%1)</source>
        <translation>Band (%1)</translation>
    </message>
    <message>
        <location line="-97"/>
        <source>verdict</source>
        <translation>Urteil</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 PSO iterations, Eq. 2.9 %2 → %3</source>
        <translation>%1 PSO-Iterationen, Gl. 2.9 %2 → %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>least squares, b1 = %1</source>
        <translation>kleinste Quadrate, b1 = %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>least squares, unstable: b1 = %1 ≤ 0</source>
        <translation>kleinste Quadrate, instabil: b1 = %1 ≤ 0</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 LM epochs (%2)</source>
        <translation>%1 LM-Epochen (%2)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source> (%1 s)</source>
        <translation> (%1 s)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+69"/>
        <source>diverges</source>
        <translation>divergiert</translation>
    </message>
    <message>
        <location line="-60"/>
        <source>fit, %1</source>
        <translation>Anpassung, %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>held out, %1</source>
        <translation>Testdaten, %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Training: %1.</source>
        <translation>Training: %1.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The modular case could not be computed: %1</source>
        <translation>Der modulare Fall konnte nicht berechnet werden: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Each model is fitted on the Z-heating test (%1) and the C-heating test (%2) together and predicts the combined helical test (%3), which it has not seen. Target %4, inputs %5, seed 1. Error reduction as the paper states it: 1 − max|residual| / max|error|, and by RMS.</source>
        <translation>Jedes Modell wird gemeinsam an den Z-Erwärmungstest (%1) und den C-Erwärmungstest (%2) angepasst und sagt den kombinierten Helix-Test (%3) vorher, den es nicht gesehen hat. Zielgröße %4, Eingänge %5, Startwert 1. Fehlerverringerung wie in der Veröffentlichung: 1 − max|Residuum| / max|Fehler| sowie nach RMS.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>less, peak</source>
        <translation>weniger, Spitze</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>less, RMS</source>
        <translation>weniger, RMS</translation>
    </message>
</context>
<context>
    <name>metrofit::ReportExporter</name>
    <message>
        <location filename="../app/gui/reportexporter.cpp" line="+39"/>
        <source>the unsaved project</source>
        <translation>das ungespeicherte Projekt</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot prepare the report: %1</source>
        <translation>Der Bericht kann nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <location line="+20"/>
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
    <name>metrofit::ReportModelDialog</name>
    <message>
        <location filename="../widgets/setup/reportmodeldialog.cpp" line="+40"/>
        <source>Create setup model from report %1</source>
        <translation>Einrichtmodell aus dem Bericht %1 erstellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add report features to setup model</source>
        <translation>Merkmale des Berichts zum Einrichtmodell hinzufügen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The %1 “%2” measures these characteristics. The checked ones become the dimensions of a new setup model, each under a feature node; draw the real relation graph in the Graph tab afterwards.</source>
        <translation>Der %1 „%2“ misst diese Merkmale. Die angehakten werden die Maße eines neuen Einrichtmodells, jedes unter einem Formelement-Knoten; den tatsächlichen Beziehungsgraphen zeichnen Sie danach im Reiter Graph.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The %1 “%2” measures these characteristics. The checked ones are added to the setup model “%3” as dimensions; those it reads already are marked.</source>
        <translation>Der %1 „%2“ misst diese Merkmale. Die angehakten werden dem Einrichtmodell „%3“ als Maße hinzugefügt; die es bereits liest, sind markiert.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Feature</source>
        <translation>Element</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Characteristic</source>
        <translation>Merkmal</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Nominal</source>
        <translation>Nennwert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lower tol.</source>
        <translation>Untere Tol.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Upper tol.</source>
        <translation>Obere Tol.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>State</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>in the model (%1)</source>
        <translation>im Modell (%1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the report prints no nominal for it</source>
        <translation>das Protokoll druckt keinen Sollwert dafür</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an angle (deg), not a length a setup correction moves</source>
        <translation>ein Winkel (°), keine Länge, die eine Einrichtdatenkorrektur verschiebt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot be used: %1</source>
        <translation>nicht verwendbar: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no tolerance printed: takes ± the value below</source>
        <translation>keine Toleranz gedruckt: erhält ± den Wert unten</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Check &amp;all</source>
        <translation>&amp;Alle anhaken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check &amp;none</source>
        <translation>&amp;Keine anhaken</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The machine axis the corrections act along</source>
        <translation>Die Maschinenachse, entlang der die Korrekturen wirken</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model &amp;name:</source>
        <translation>Modell&amp;name:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;xis:</source>
        <translation>A&amp;chse:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>(none: draw the arcs yourself)</source>
        <translation>(keine: Kanten selbst zeichnen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Each new feature gets an arc (+1) from this setup datum, so the model can run at once; change the arcs in the Graph tab</source>
        <translation>Jedes neue Formelement erhält eine Kante (+1) von diesem Einrichtdatum, damit das Modell sofort rechnen kann; die Kanten ändern Sie im Reiter Graph</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Connect new features to:</source>
        <translation>Neue Elemente &amp;verbinden mit:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>± limits for values the report prints no tolerance for (0: such values cannot be added)</source>
        <translation>±-Grenzen für Werte, für die der Bericht keine Toleranz druckt (0: solche Werte können nicht hinzugefügt werden)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Tolerance where the report gives none: ±</source>
        <translation>&amp;Toleranz, wo der Bericht keine angibt: ±</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Create model</source>
        <translation>Modell erstellen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Add to model</source>
        <translation>Zum Modell hinzufügen</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Check the characteristics to add.</source>
        <translation>Haken Sie die hinzuzufügenden Merkmale an.</translation>
    </message>
    <message numerus="yes">
        <location line="+26"/>
        <source>%n dimension(s) to add; the model will have %1 features and %2 dimensions.</source>
        <translation>
            <numerusform>%n Maß hinzuzufügen; das Modell wird %1 Formelemente und %2 Maße haben.</numerusform>
            <numerusform>%n Maße hinzuzufügen; das Modell wird %1 Formelemente und %2 Maße haben.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>metrofit::ResidualCheck</name>
    <message>
        <location filename="../widgets/diagnose/residualchecktext.cpp" line="+34"/>
        <source>Ljung-Box</source>
        <translation>Ljung-Box</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>F test</source>
        <translation>F-Test</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>file row</source>
        <translation>Dateizeile</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>path angle</source>
        <translation>Bahnwinkel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>loop direction</source>
        <translation>Umlaufrichtung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>samples since reversal</source>
        <translation>Abtastwerte seit Umkehr</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>along the normal</source>
        <translation>entlang der Normalen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part</source>
        <translation>Werkstück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dimension</source>
        <translation>Maß</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>surface</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>normal %1</source>
        <translation>Normale %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+140"/>
        <source>dimension %1</source>
        <translation>Maß %1</translation>
    </message>
    <message>
        <location line="-133"/>
        <source>time</source>
        <comment>in a sentence</comment>
        <translation>der Zeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the order of the rows in the file</source>
        <translation>der Reihenfolge der Zeilen in der Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the path angle</source>
        <translation>dem Bahnwinkel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the direction of the loop (counter-clockwise or clockwise)</source>
        <translation>der Umlaufrichtung (gegen oder im Uhrzeigersinn)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the number of samples since an axis reversed</source>
        <translation>der Zahl der Abtastwerte seit einer Achsumkehr</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the nominal %1 coordinate</source>
        <translation>der nominalen %1-Koordinate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the position along the nominal normal</source>
        <translation>der Lage entlang der nominalen Normalen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the part</source>
        <translation>dem Werkstück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the dimension</source>
        <translation>dem Maß</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the surface</source>
        <translation>der Fläche</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the %1 component of the nominal normal</source>
        <translation>der %1-Komponente der nominalen Normalen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the position on surface %1</source>
        <translation>der Lage auf der Fläche %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dimension %1</source>
        <comment>in a sentence</comment>
        <translation>dem Maß %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>column %1</source>
        <translation>der Spalte %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>linear</source>
        <translation>linear</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>smooth</source>
        <translation>glatt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>step</source>
        <translation>Sprung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>periodic</source>
        <translation>periodisch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per level</source>
        <translation>je Stufe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spike</source>
        <translation>Spitze</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 min</source>
        <comment>a period</comment>
        <translation>%1 min</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>periodic, period %1</source>
        <translation>periodisch, Periode %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>a cycle with a period of %1</source>
        <translation>ein Zyklus mit der Periode %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a linear trend</source>
        <translation>ein linearer Trend</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a smooth curve</source>
        <translation>eine glatte Kurve</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a step</source>
        <translation>ein Sprung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a step at %1</source>
        <translation>ein Sprung bei %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a periodic pattern</source>
        <translation>ein periodisches Muster</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a different level per group</source>
        <translation>ein eigenes Niveau je Gruppe</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1 (%2, %3 % of the residual variance)</source>
        <translation>%1 (%2, %3 % der Residuenvarianz)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>white: no test finds structure</source>
        <translation>weiß: kein Test findet Struktur</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>Warning: the held-out error rose from %1 to %2 %3 with the accepted effects. They describe the fit rows but do not carry over to the rows they did not see: do not compensate with them.</source>
        <translation>Warnung: der Fehler der zurückgehaltenen Zeilen stieg mit den übernommenen Effekten von %1 auf %2 %3. Sie beschreiben die Anpassungszeilen, übertragen sich aber nicht auf die Zeilen, die sie nicht sahen: nicht damit kompensieren.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>On the held-out rows, which only report the error, the residual looks like noise as well.</source>
        <translation>In den zurückgehaltenen Zeilen, die nur den Fehler berichten, sieht das Residuum ebenfalls wie Rauschen aus.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>On the held-out rows, which only report the error, the residual still depends on %1: the model misses something there that the fit rows did not show.</source>
        <translation>In den zurückgehaltenen Zeilen, die nur den Fehler berichten, hängt das Residuum noch von %1 ab: dem Modell fehlt dort etwas, das die Anpassungszeilen nicht zeigten.</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n held-out measurement(s) left out of the held-out error as gross errors: %1.</source>
        <translation>
            <numerusform>%n zurückgehaltener Messwert als grober Fehler aus dem Fehler der zurückgehaltenen Zeilen ausgelassen: %1.</numerusform>
            <numerusform>%n zurückgehaltene Messwerte als grobe Fehler aus dem Fehler der zurückgehaltenen Zeilen ausgelassen: %1.</numerusform>
        </translation>
    </message>
    <message>
        <location line="-134"/>
        <source>not white: still depends on %1</source>
        <translation>nicht weiß: hängt noch ab von %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not white: the tests find structure that no single variable explains</source>
        <translation>nicht weiß: die Tests finden Struktur, die keine einzelne Variable erklärt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>row %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part %1</source>
        <translation>Werkstück %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>point %1</source>
        <translation>Punkt %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>observation %1</source>
        <translation>Beobachtung %1</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>What is left unexplained: nothing that the tests can find. None of the %n test(s) of the final residual (against every variable the data offer, and of its serial correlation) finds a dependence at the %1 % family-wise level: the residual looks like noise.</source>
        <translation>
            <numerusform>Was unerklärt bleibt: nichts, was die Tests finden können. Der %n Test des endgültigen Residuums (gegen jede Variable der Daten und auf serielle Korrelation) findet keine Abhängigkeit auf dem familienweisen Niveau von %1 %: das Residuum sieht aus wie Rauschen.</numerusform>
            <numerusform>Was unerklärt bleibt: nichts, was die Tests finden können. Keiner der %n Tests des endgültigen Residuums (gegen jede Variable der Daten und auf serielle Korrelation) findet eine Abhängigkeit auf dem familienweisen Niveau von %1 %: das Residuum sieht aus wie Rauschen.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+79"/>
        <source>%1 (%2, %3 % of the residual variance, p = %4)</source>
        <translation>%1 (%2, %3 % der Residuenvarianz, p = %4)</translation>
    </message>
    <message>
        <location line="-70"/>
        <source>%1 and %2</source>
        <translation>%1 und %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What is left unexplained: the final residual still depends on %1. No effect of the catalogue explains this (tests at the %2 % family-wise level).</source>
        <translation>Was unerklärt bleibt: das endgültige Residuum hängt noch ab von %1. Kein Effekt des Katalogs erklärt das (Tests auf dem familienweisen Niveau von %2 %).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What is left unexplained: the final residual is serially correlated in the order of %1 (Ljung-Box test, p = %2), but no single variable of the data explains it.</source>
        <translation>Was unerklärt bleibt: das endgültige Residuum ist in der Reihenfolge %1 seriell korreliert (Ljung-Box-Test, p = %2), aber keine einzelne Variable der Daten erklärt das.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>What is left unexplained: the tests find structure in the final residual at the %1 % family-wise level that no single variable explains.</source>
        <translation>Was unerklärt bleibt: die Tests finden auf dem familienweisen Niveau von %1 % Struktur im endgültigen Residuum, die keine einzelne Variable erklärt.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 in %2</source>
        <translation>%1 in %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No effect of the catalogue explains part of this structure, so the model was given a generic term for it instead of a wrong name: %1.</source>
        <translation>Kein Effekt des Katalogs erklärt einen Teil dieser Struktur, daher erhielt das Modell dafür einen generischen Term statt eines falschen Namens: %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No measurement was excluded as a gross error (robust z above %1).</source>
        <translation>Kein Messwert wurde als grober Fehler ausgeschlossen (robustes z über %1).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No measurement was excluded as a gross error.</source>
        <translation>Kein Messwert wurde als grober Fehler ausgeschlossen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (residual %2 %3, robust z %4)</source>
        <translation>%1 (Residuum %2 %3, robustes z %4)</translation>
    </message>
    <message numerus="yes">
        <location line="-95"/>
        <location line="+100"/>
        <source> and %n more</source>
        <translation>
            <numerusform> und %n weiterer</numerusform>
            <numerusform> und %n weitere</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n measurement(s) excluded from the fit as gross errors (robust z above %1): %2.</source>
        <translation>
            <numerusform>%n Messwert als grober Fehler von der Anpassung ausgeschlossen (robustes z über %1): %2.</numerusform>
            <numerusform>%n Messwerte als grobe Fehler von der Anpassung ausgeschlossen (robustes z über %1): %2.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>metrofit::ResidualCheckView</name>
    <message>
        <location filename="../widgets/diagnose/residualcheckview.cpp" line="+122"/>
        <source>Final residual against %1</source>
        <translation>Endgültiges Residuum über %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Final residual against %1 with the generic fit (%2)</source>
        <translation>Endgültiges Residuum über %1 mit der generischen Anpassung (%2)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+163"/>
        <location line="+283"/>
        <source>residual</source>
        <translation>Residuum</translation>
    </message>
    <message>
        <location line="-445"/>
        <source>residual (%1)</source>
        <translation>Residuum (%1)</translation>
    </message>
    <message>
        <location line="+167"/>
        <source>generic fit</source>
        <translation>generische Anpassung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>generic fit, %1</source>
        <translation>generische Anpassung, %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+290"/>
        <source>excluded outliers</source>
        <translation>ausgeschlossene Ausreißer</translation>
    </message>
    <message>
        <location line="-249"/>
        <location line="+143"/>
        <source>What the residual still depends on (strongest first):</source>
        <translation>Wovon das Residuum noch abhängt (stärkste zuerst):</translation>
    </message>
    <message>
        <location line="-142"/>
        <source>Outliers excluded from the fit:</source>
        <translation>Von der Anpassung ausgeschlossene Ausreißer:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tests of the final residual:</source>
        <translation>Tests des endgültigen Residuums:</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The final residual (after every accepted effect, outliers excluded) is white when no test finds structure at the family-wise level (Holm&apos;s procedure over all tests)</source>
        <translation>Das endgültige Residuum (nach allen übernommenen Effekten, ohne Ausreißer) ist weiß, wenn kein Test auf dem familienweisen Niveau Struktur findet (Holm-Verfahren über alle Tests)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+11"/>
        <source>Form</source>
        <translation>Form</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Share (%)</source>
        <translation>Anteil (%)</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+12"/>
        <source>p-value</source>
        <translation>p-Wert</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Per variable with a rejected test its strongest form; share = part of the residual variance the form explains</source>
        <translation>Je Variable mit abgelehntem Test ihre stärkste Form; Anteil = Teil der Residuenvarianz, den die Form erklärt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Row</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Part</source>
        <translation>Werkstück</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Dimension</source>
        <translation>Maß</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Id</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+139"/>
        <source>Residual</source>
        <translation>Residuum</translation>
    </message>
    <message>
        <location line="-139"/>
        <source>Robust z</source>
        <translation>Robustes z</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Observations whose robust z (|r - median| / (1.4826 MAD)) is above the threshold: gross errors, excluded and the model refitted without them</source>
        <translation>Beobachtungen, deren robustes z (|r - Median| / (1,4826 MAD)) über der Schwelle liegt: grobe Fehler, ausgeschlossen und das Modell ohne sie neu angepasst</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Test</source>
        <translation>Test</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Order / variable</source>
        <translation>Reihenfolge / Variable</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Statistic</source>
        <translation>Statistik</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>df</source>
        <translation>FG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rejected</source>
        <translation>Abgelehnt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ljung-Box: serial correlation of the residual in that order (chi-square); F test: the residual against the variable in that form (nested models). Rejected: by Holm&apos;s procedure at the family-wise level</source>
        <translation>Ljung-Box: serielle Korrelation des Residuums in dieser Reihenfolge (Chi-Quadrat); F-Test: das Residuum gegen die Variable in dieser Form (geschachtelte Modelle). Abgelehnt: nach dem Holm-Verfahren auf dem familienweisen Niveau</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Residual check: run the diagnosis (Ctrl+R).</source>
        <translation>Residuenprüfung: Diagnose starten (Strg+R).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Final residual: run the diagnosis (Ctrl+R)</source>
        <translation>Endgültiges Residuum: Diagnose starten (Strg+R)</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+1"/>
        <source>This diagnosis has no residual check.</source>
        <translation>Diese Diagnose hat keine Residuenprüfung.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>What the residual still depends on: nothing found.</source>
        <translation>Wovon das Residuum noch abhängt: nichts gefunden.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Outliers: none (robust z threshold %1).</source>
        <translation>Ausreißer: keine (Schwelle des robusten z %1).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Outliers: none.</source>
        <translation>Ausreißer: keine.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outliers excluded from the fit (robust z above %1):</source>
        <translation>Von der Anpassung ausgeschlossene Ausreißer (robustes z über %1):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Residual (%1)</source>
        <translation>Residuum (%1)</translation>
    </message>
    <message numerus="yes">
        <location line="+21"/>
        <source>Tests of the final residual (%n test(s), %1 observations; rejected by Holm at the %2 % family-wise level):</source>
        <translation>
            <numerusform>Tests des endgültigen Residuums (%n Test, %1 Beobachtungen; abgelehnt nach Holm auf dem familienweisen Niveau von %2 %):</numerusform>
            <numerusform>Tests des endgültigen Residuums (%n Tests, %1 Beobachtungen; abgelehnt nach Holm auf dem familienweisen Niveau von %2 %):</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rejected at %1 %</source>
        <translation>Abgelehnt bei %1 %</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>The final residual is white: nothing left to plot</source>
        <translation>Das endgültige Residuum ist weiß: nichts mehr darzustellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No single variable explains the structure left</source>
        <translation>Keine einzelne Variable erklärt die verbleibende Struktur</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>generic fit (%1)</source>
        <translation>generische Anpassung (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>generic fit (%1), %2</source>
        <translation>generische Anpassung (%1), %2</translation>
    </message>
    <message numerus="yes">
        <location line="+48"/>
        <source>(index of %n level(s))</source>
        <translation>
            <numerusform>(Index von %n Stufe)</numerusform>
            <numerusform>(Index von %n Stufen)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>metrofit::ResidualPlot</name>
    <message>
        <location filename="../widgets/diagnose/residualplot.cpp" line="-283"/>
        <source>before the effect</source>
        <translation>vor dem Effekt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>after</source>
        <translation>nachher</translation>
    </message>
    <message>
        <location line="+22"/>
        <source> (arrows × %1)</source>
        <translation> (Pfeile × %1)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
</context>
<context>
    <name>metrofit::ResidualPlotView</name>
    <message>
        <location line="+93"/>
        <source>Residual plot: run the diagnosis (Ctrl+R)</source>
        <translation>Residuendiagramm: Diagnose ausführen (Strg+R)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>residual before the effect</source>
        <translation>Residuum vor dem Effekt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>after</source>
        <translation>nachher</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupCharts</name>
    <message>
        <location filename="../widgets/setup/setupcharts.cpp" line="+60"/>
        <source>exact</source>
        <translation>exakt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1, seed %2</source>
        <translation>%1, Startwert %2</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>solid: f1</source>
        <translation>durchgezogen: f1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dashed: f2 = |x|</source>
        <translation>gestrichelt: f2 = |x|</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dotted: f = 10 f1 − f2 (right axis)</source>
        <translation>gepunktet: f = 10 f1 − f2 (rechte Achse)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>solutions evaluated</source>
        <translation>bewertete Lösungen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>f1, f2 (mm)</source>
        <translation>f1, f2 (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+105"/>
        <source>f1 (mm)</source>
        <translation>f1 (mm)</translation>
    </message>
    <message>
        <location line="-103"/>
        <source>f = 10 f1 − f2 (mm)</source>
        <translation>f = 10 f1 − f2 (mm)</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>exact optimum f1 = %1 mm</source>
        <translation>exaktes Optimum f1 = %1 mm</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>exact f = %1</source>
        <translation>exaktes f = %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>measurement set, sorted by f1 before correction</source>
        <translation>Messreihe, sortiert nach f1 vor der Korrektur</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>before correction</source>
        <translation>vor der Korrektur</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exact optimum</source>
        <translation>exaktes Optimum</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 trials</source>
        <translation>%1 Versuche</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupConvergenceView</name>
    <message>
        <location filename="../widgets/setup/setupconvergenceview.cpp" line="+32"/>
        <source>Show f&amp;2 = |x|</source>
        <translation>f&amp;2 = |x|</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show f = &amp;10 f1 − f2</source>
        <translation>f = &amp;10 f1 − f2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The size of the correction vector, mm (minimised among the f1-optimal)</source>
        <translation>Die Größe des Korrekturvektors, mm (minimiert unter den f1-optimalen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The single objective the metaheuristics maximise (right axis)</source>
        <translation>Die einzelne Zielfunktion, die die Metaheuristiken maximieren (rechte Achse)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Best solution so far against the number of solutions evaluated.</source>
        <translation>Bisher beste Lösung über der Zahl bewerteter Lösungen.</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupGraphEditor</name>
    <message>
        <location filename="../widgets/setup/setupgrapheditor.cpp" line="+94"/>
        <source>Add node…</source>
        <translation>Knoten hinzufügen…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Add a machine point, work offset, tool, feature or dimension</source>
        <translation>Einen Maschinenpunkt, eine Nullpunktverschiebung, ein Werkzeug, ein Formelement oder ein Maß hinzufügen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add arc…</source>
        <translation>Kante hinzufügen…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Add an arc with weight +1 or −1</source>
        <translation>Eine Kante mit Gewicht +1 oder −1 hinzufügen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edit…</source>
        <translation>Bearbeiten…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rename the selected node or change its kind; flip the weight of the selected arc</source>
        <translation>Den ausgewählten Knoten umbenennen oder seine Art ändern; das Gewicht der ausgewählten Kante umkehren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Remove the selected node (with its arcs) or arc</source>
        <translation>Den ausgewählten Knoten (mit seinen Kanten) oder die Kante entfernen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Redo</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Undo the last edit of the graph (Ctrl+Z while the graph has the focus)</source>
        <translation>Die letzte Änderung am Graphen rückgängig machen (Strg+Z, wenn der Graph den Fokus hat)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Redo (Ctrl+Shift+Z while the graph has the focus)</source>
        <translation>Wiederherstellen (Strg+Umschalt+Z, wenn der Graph den Fokus hat)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Zoom in</source>
        <translation>Vergrößern</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Zoom in (Ctrl+wheel)</source>
        <translation>Vergrößern (Strg+Mausrad)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Zoom out</source>
        <translation>Verkleinern</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Zoom out (Ctrl+wheel)</source>
        <translation>Verkleinern (Strg+Mausrad)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fit the whole graph into the view</source>
        <translation>Den ganzen Graphen in die Ansicht einpassen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rows</source>
        <translation>Zeilen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Levels in rows instead of columns</source>
        <translation>Ebenen in Zeilen statt in Spalten</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export SVG…</source>
        <translation>SVG exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the graph as an SVG drawing</source>
        <translation>Den Graphen als SVG-Zeichnung speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export PNG…</source>
        <translation>PNG exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the graph as a PNG image</source>
        <translation>Den Graphen als PNG-Bild speichern</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the graph as an SVG drawing or a PNG image</source>
        <translation>Den Graphen als SVG-Zeichnung oder PNG-Bild speichern</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Dimension</source>
        <translation>Maß</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Nominal
(mm)</source>
        <translation>Nennmaß
(mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lower
(mm)</source>
        <translation>Unten
(mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Upper
(mm)</source>
        <translation>Oben
(mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Report
feature</source>
        <translation>Berichts-
merkmal</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+152"/>
        <source>What the CMM report calls the dimension (feature:value, a DMIS label); empty: its id</source>
        <translation>Wie der KMG-Bericht das Maß nennt (Element:Wert, ein DMIS-Label); leer: seine ID</translation>
    </message>
    <message>
        <location line="-150"/>
        <source>Lower tolerance limit relative to the nominal, mm</source>
        <translation>Untere Toleranzgrenze relativ zum Nennmaß, mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Upper tolerance limit relative to the nominal, mm</source>
        <translation>Obere Toleranzgrenze relativ zum Nennmaß, mm</translation>
    </message>
    <message numerus="yes">
        <location line="+68"/>
        <source>… and %n more problem(s)</source>
        <translation>
            <numerusform>… und %n weiteres Problem</numerusform>
            <numerusform>… und %n weitere Probleme</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>The model has %n problem(s) (outlined in red):</source>
        <translation>
            <numerusform>Das Modell hat %n Problem (rot umrandet):</numerusform>
            <numerusform>Das Modell hat %n Probleme (rot umrandet):</numerusform>
        </translation>
    </message>
    <message>
        <location line="+29"/>
        <source>The study&apos;s report has no feature “%1”</source>
        <translation>Der Bericht der Studie hat kein Merkmal „%1“</translation>
    </message>
    <message numerus="yes">
        <location line="+51"/>
        <source>What the %1 calls the dimension (%n feature(s) offered); empty: its id</source>
        <translation>
            <numerusform>Wie der %1 das Maß nennt (%n Merkmal angeboten); leer: seine ID</numerusform>
            <numerusform>Wie der %1 das Maß nennt (%n Merkmale angeboten); leer: seine ID</numerusform>
        </translation>
    </message>
    <message>
        <location line="+54"/>
        <location line="+20"/>
        <source>Add node</source>
        <translation>Knoten hinzufügen</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>&amp;Level:</source>
        <translation>&amp;Ebene:</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+64"/>
        <source>&amp;Id:</source>
        <translation>&amp;Kennung:</translation>
    </message>
    <message>
        <location line="-59"/>
        <location line="+68"/>
        <source>The id &quot;%1&quot; is empty or already used by another node.</source>
        <translation>Die Kennung „%1“ ist leer oder wird bereits von einem anderen Knoten verwendet.</translation>
    </message>
    <message>
        <location line="-60"/>
        <location line="+30"/>
        <source>Add arc</source>
        <translation>Kante hinzufügen</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>+1 (the target moves with the source)</source>
        <translation>+1 (das Ziel bewegt sich mit der Quelle)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>−1 (the target moves against the source)</source>
        <translation>−1 (das Ziel bewegt sich gegen die Quelle)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;From:</source>
        <translation>&amp;Von:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;To:</source>
        <translation>&amp;Nach:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Weight:</source>
        <translation>&amp;Gewicht:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The arc %1 → %2 exists already or an end is empty.</source>
        <translation>Die Kante %1 → %2 existiert bereits oder ein Ende ist leer.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Edit %1</source>
        <translation>%1 bearbeiten</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Kind:</source>
        <translation>&amp;Art:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Edit node</source>
        <translation>Knoten bearbeiten</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Export graph as SVG</source>
        <translation>Graph als SVG exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Export graph as PNG</source>
        <translation>Graph als PNG exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SVG drawings (*.svg)</source>
        <translation>SVG-Zeichnungen (*.svg)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot export the graph</source>
        <translation>Der Graph kann nicht exportiert werden</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupGraphView</name>
    <message>
        <location filename="../widgets/setup/setupgraphview.cpp" line="+311"/>
        <source>Unknown nodes</source>
        <translation>Unbekannte Knoten</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&apos;%1&apos; is not a node of the model (an arc names it)</source>
        <translation>„%1“ ist kein Knoten des Modells (eine Kante verweist darauf)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 → %2, weight %3</source>
        <translation>%1 → %2, Gewicht %3</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>weight −1: the target moves against the source</source>
        <translation>Gewicht −1: das Ziel bewegt sich gegen die Quelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>weight +1: the target moves with the source</source>
        <translation>Gewicht +1: das Ziel bewegt sich mit der Quelle</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>red outline: a problem of the model (see its tooltip)</source>
        <translation>rote Umrandung: ein Problem des Modells (siehe Tooltip)</translation>
    </message>
    <message>
        <location line="+143"/>
        <location line="+22"/>
        <location line="+18"/>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>Relation graph of %1</source>
        <translation>Beziehungsgraph von %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setup model: machine points, work offsets, tools, features, dimensions</source>
        <translation>Einrichtmodell: Maschinenpunkte, Nullpunktverschiebungen, Werkzeuge, Formelemente, Maße</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write %1: the SVG generator did not start</source>
        <translation>%1 kann nicht geschrieben werden: der SVG-Generator ist nicht gestartet</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupMargins</name>
    <message>
        <location filename="../widgets/setup/setupmargins.cpp" line="+81"/>
        <source>tolerance zone</source>
        <translation>Toleranzzone</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>before: deviation and margin to the nearer limit</source>
        <translation>vorher: Abweichung und Abstand zur näheren Grenze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>after correction</source>
        <translation>nach der Korrektur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of tolerance</source>
        <translation>außerhalb der Toleranz</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>deviation from nominal (mm)</source>
        <translation>Abweichung vom Nennmaß (mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>margin (mm)</source>
        <translation>Abstand (mm)</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupMarginsWidget</name>
    <message>
        <location line="+54"/>
        <source>Run a method to see the margins before and after correction.</source>
        <translation>Eine Methode ausführen, um die Abstände vor und nach der Korrektur zu sehen.</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupModelEditor</name>
    <message>
        <location filename="../widgets/setup/setupmodeleditor.cpp" line="+67"/>
        <source>Machine points (M)</source>
        <translation>Maschinenpunkte (M)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Work offsets (W)</source>
        <translation>Nullpunktverschiebungen (W)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tools (T)</source>
        <translation>Werkzeuge (T)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Features (F)</source>
        <translation>Formelemente (F)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Dimensions (D)</source>
        <translation>Maße (D)</translation>
    </message>
    <message>
        <location line="+160"/>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Remove %1</source>
        <translation>%1 entfernen</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Change the kind of %1</source>
        <translation>Art von %1 ändern</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Add arc %1 → %2</source>
        <translation>Kante %1 → %2 hinzufügen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Remove arc %1 → %2</source>
        <translation>Kante %1 → %2 entfernen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Set weight of %1 → %2 to %3</source>
        <translation>Gewicht von %1 → %2 auf %3 setzen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Edit tolerance of %1</source>
        <translation>Toleranz von %1 bearbeiten</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Clear the report feature of %1</source>
        <translation>Berichtsmerkmal von %1 entfernen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Map %1 to the report feature %2</source>
        <translation>%1 dem Berichtsmerkmal %2 zuordnen</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupPage</name>
    <message>
        <location filename="../app/gui/setuppage.cpp" line="+152"/>
        <source>&amp;Save model</source>
        <translation>Modell &amp;speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;vert</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Run</source>
        <translation>A&amp;usführen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;lear chart</source>
        <translation>Diagramm lee&amp;ren</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Write the edited model to its dataset file</source>
        <translation>Das bearbeitete Modell in seine Datensatzdatei schreiben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read the model file again (one undo step: Ctrl+Z brings the edits back)</source>
        <translation>Die Modelldatei neu einlesen (ein Rückgängig-Schritt: Strg+Z holt die Änderungen zurück)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cannot save the setup model</source>
        <translation>Das Einrichtmodell kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot revert the setup model</source>
        <translation>Das Einrichtmodell kann nicht zurückgesetzt werden</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>exact: the LP/MILP optimum (GLPK); the metaheuristics with the paper&apos;s settings</source>
        <translation>exakt: das LP/MILP-Optimum (GLPK); die Metaheuristiken mit den Einstellungen der Veröffentlichung</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> solutions</source>
        <translation> Lösungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Solutions a metaheuristic evaluates (the paper: 5000)</source>
        <translation>Anzahl der Lösungen, die eine Metaheuristik bewertet (Veröffentlichung: 5000)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Seed of the metaheuristic: the same seed gives the same run</source>
        <translation>Startwert der Metaheuristik: derselbe Startwert ergibt denselben Lauf</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the method (Ctrl+R)</source>
        <translation>Die Methode ausführen (Strg+R)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Method:</source>
        <translation>&amp;Methode:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Budget:</source>
        <translation>B&amp;udget:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>S&amp;eed:</source>
        <translation>S&amp;tartwert:</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>&amp;Graph</source>
        <translation>&amp;Graph</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R&amp;un</source>
        <translation>&amp;Lauf</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Res&amp;ults</source>
        <translation>&amp;Ergebnisse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Va&amp;lidation</source>
        <translation>&amp;Validierung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Change the setup method</source>
        <translation>Methode der Einrichtung ändern</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Change the setup budget</source>
        <translation>Budget der Einrichtung ändern</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Change the setup seed</source>
        <translation>Startwert der Einrichtung ändern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From &amp;report…</source>
        <translation>Aus dem &amp;Bericht…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Create the setup model from a CMM report of the project, or add the report&apos;s features the model lacks</source>
        <translation>Das Einrichtmodell aus einem KMG-Bericht des Projekts erstellen oder die Merkmale des Berichts hinzufügen, die dem Modell fehlen</translation>
    </message>
    <message>
        <location line="+112"/>
        <source>The applied effects cannot be used: %1</source>
        <translation>Die übernommenen Effekte können nicht verwendet werden: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>This project has no setup model and no CMM report. Import a CMM report (File › Import), then create the model from it with “From report…”.</source>
        <translation>Dieses Projekt hat kein Einrichtmodell und keinen KMG-Bericht. Importieren Sie einen KMG-Bericht (Datei › Importieren) und erstellen Sie daraus das Modell mit „Aus dem Bericht…“.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This project has no setup model yet. Create it from the CMM report “%1” with “From report…” (or the report&apos;s context menu in the project navigator).</source>
        <translation>Dieses Projekt hat noch kein Einrichtmodell. Erstellen Sie es aus dem KMG-Bericht „%1“ mit „Aus dem Bericht…“ (oder über das Kontextmenü des Berichts im Projektnavigator).</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>The project has no CMM report: import one first (File › Import).</source>
        <translation>Das Projekt hat keinen KMG-Bericht: importieren Sie zuerst einen (Datei › Importieren).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” is not a CMM report (OGP, PC-DMIS, DMIS, DFQ, Calypso, QIF) of the project.</source>
        <translation>„%1“ ist kein KMG-Protokoll (OGP, PC-DMIS, DMIS, DFQ, Calypso, QIF) des Projekts.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>“%1” is not a dataset of the project.</source>
        <translation>„%1“ ist kein Datensatz des Projekts.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The project has no setup model to add features to.</source>
        <translation>Das Projekt hat kein Einrichtmodell, dem Merkmale hinzugefügt werden könnten.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save or revert the edits of the setup model before you add the features of another report.</source>
        <translation>Speichern oder verwerfen Sie die Änderungen am Einrichtmodell, bevor Sie die Merkmale eines anderen Berichts hinzufügen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Use the report %1 for the setup study</source>
        <translation>Den Bericht %1 für die Einricht-Studie verwenden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add report features to the setup model</source>
        <translation>Merkmale des Berichts zum Einrichtmodell hinzufügen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The model reads every checked characteristic already.</source>
        <translation>Das Modell liest jedes angehakte Merkmal bereits.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot create the folder %1 for the setup model.</source>
        <translation>Der Ordner %1 für das Einrichtmodell kann nicht angelegt werden.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Setup model made from the CMM report %1</source>
        <translation>Einrichtmodell, erstellt aus dem KMG-Bericht %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Create setup model %1 from report %2</source>
        <translation>Einrichtmodell %1 aus dem Bericht %2 erstellen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cannot read the CMM report</source>
        <translation>Der KMG-Bericht kann nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>This project has no CMM report for the setup study (a dataset of kind &quot;cmm_report&quot;).</source>
        <translation>Dieses Projekt hat keinen KMG-Messbericht für die Einrichtstudie (ein Datensatz der Art „cmm_report“).</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The project has no setup model dataset to revert to.</source>
        <translation>Das Projekt hat keinen Einrichtmodell-Datensatz zum Zurücksetzen.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Revert the setup model</source>
        <translation>Einrichtmodell zurücksetzen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Recover autosaved model edits</source>
        <translation>Automatisch gesicherte Modelländerungen wiederherstellen</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+468"/>
        <source>No result for this model yet: choose a method and press Run (Ctrl+R).</source>
        <translation>Noch kein Ergebnis für dieses Modell: Methode wählen und Ausführen drücken (Strg+R).</translation>
    </message>
    <message numerus="yes">
        <location line="-458"/>
        <source>The edited model has %n problem(s), the first: %1</source>
        <translation>
            <numerusform>Das bearbeitete Modell hat %n Problem: %1</numerusform>
            <numerusform>Das bearbeitete Modell hat %n Probleme, das erste: %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+26"/>
        <source>studies.setup.budget: must be a whole number of solutions</source>
        <translation>studies.setup.budget: muss eine ganze Zahl von Lösungen sein</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>studies.setup.budget: more solutions than the page can run (at most %1)</source>
        <translation>studies.setup.budget: mehr Lösungen, als die Seite ausführen kann (höchstens %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>studies.setup.seed: larger than the page can use (at most %1)</source>
        <translation>studies.setup.seed: größer, als die Seite verwenden kann (höchstens %1)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Model “%1” (%2): %3 setup data (%4 work offsets, %5 tools, %6 machine points), %7 features, %8 dimensions, %9 arcs; axis %10, grid %11 mm, bounds [%12, %13] mm.</source>
        <translation>Modell „%1“ (%2): %3 Einrichtdaten (%4 Nullpunktverschiebungen, %5 Werkzeuge, %6 Maschinenpunkte), %7 Formelemente, %8 Maße, %9 Kanten; Achse %10, Raster %11 mm, Grenzen [%12; %13] mm.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Edited, not saved.</source>
        <translation>Bearbeitet, nicht gespeichert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Report “%1”: %2 parts, %3 rows.</source>
        <translation>Bericht „%1“: %2 Werkstücke, %3 Zeilen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Smallest error budget before correction f1 = %1 mm.</source>
        <translation>Kleinstes Fehlerbudget vor der Korrektur f1 = %1 mm.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>deviations predicted for part %1; residual rms %2 mm (declared model %3 mm)</source>
        <translation>Abweichungen vorhergesagt für Werkstück %1; Residuum rms %2 mm (deklariertes Modell %3 mm)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>, last part predicted from the others %1 mm (declared %2 mm)</source>
        <translation>, letztes Werkstück aus den übrigen vorhergesagt %1 mm (deklariert %2 mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Includes applied effects: %1 — %2.</source>
        <translation>Enthält übernommene Effekte: %1 — %2.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Effects applied on the Diagnosis page belong to the report %1 (the one the diagnosis ran on); this report uses the declared model.</source>
        <translation>Die auf der Seite „Diagnose“ übernommenen Effekte gehören zum Messbericht %1 (auf dem die Diagnose lief); dieser Bericht verwendet das deklarierte Modell.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The setup study&apos;s run settings are invalid, nothing is run until they are corrected (choose a value, Undo, or the project file): %1</source>
        <translation>Die Ausführungseinstellungen der Einrichtstudie sind ungültig; nichts wird ausgeführt, bis sie korrigiert sind (einen Wert wählen, Rückgängig oder die Projektdatei): %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The setup study has no model or report to run on.</source>
        <translation>Die Einrichtstudie hat kein Modell oder keinen Bericht, auf dem sie laufen kann.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Not run: %1</source>
        <translation>Nicht ausgeführt: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Exact optimum: %1 solver calls in %2 ms.</source>
        <translation>Exaktes Optimum: %1 Solver-Aufrufe in %2 ms.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Running %1…</source>
        <translation>%1 läuft…</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>The run failed: %1</source>
        <translation>Der Lauf ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: f1 %2 mm after %3 solutions in %4 ms</source>
        <translation>%1: f1 %2 mm nach %3 Lösungen in %4 ms</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>, gap to the exact optimum %1 mm</source>
        <translation>, Abstand zum exakten Optimum %1 mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — cancelled.</source>
        <translation> — abgebrochen.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The project has no setup model dataset to save to.</source>
        <translation>Das Projekt hat keinen Einrichtmodell-Datensatz zum Speichern.</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>The model has %n problem(s); fix them before saving. The first: %1</source>
        <translation>
            <numerusform>Das Modell hat %n Problem; beheben Sie es vor dem Speichern: %1</numerusform>
            <numerusform>Das Modell hat %n Probleme; beheben Sie sie vor dem Speichern. Das erste: %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The model was saved, but the CMM report does not match it any more (the runs use the report as read against the previous model): %1</source>
        <translation>Das Modell wurde gespeichert, aber der KMG-Messbericht passt nicht mehr dazu (die Läufe verwenden den Bericht, wie er mit dem vorherigen Modell eingelesen wurde): %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>CRIPSO and PSO, seed 1, %1 solutions each, against the exact optimum.</source>
        <translation>CRIPSO und PSO, Startwert 1, je %1 Lösungen, im Vergleich zum exakten Optimum.</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>The stored result (computed %1) is out of date: the run settings, the model or the applied effects changed since. Not run with these yet: press Run (Ctrl+R).</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Ausführungseinstellungen, das Modell oder die übernommenen Effekte haben sich seitdem geändert. Damit noch nicht ausgeführt: Ausführen drücken (Strg+R).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the CMM report changed since. Press Run (Ctrl+R) to correct the setup for the report as it is now.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: der KMG-Messbericht hat sich seitdem geändert. Ausführen (Strg+R) drücken, um die Einrichtung für den Bericht in seinem jetzigen Stand zu korrigieren.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the CMM report cannot be read.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) kann nicht geprüft werden: der KMG-Messbericht ist nicht lesbar.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>From the saved project (computed %1 with these settings, this model and this report): %2: f1 %3 → %4 mm, |x| = f2 %5 mm, f %6; corrections (mm) %7; %8 of %9 parts in tolerance before, %10 after. Press Run (Ctrl+R) to see the tables and exports.</source>
        <translation>Aus dem gespeicherten Projekt (berechnet %1 mit diesen Einstellungen, diesem Modell und diesem Bericht): %2: f1 %3 → %4 mm, |x| = f2 %5 mm, f %6; Korrekturen (mm) %7; %8 von %9 Teilen vorher in Toleranz, %10 nachher. Ausführen (Strg+R) drücken, um die Tabellen und Exporte zu sehen.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Nothing is run while the setup study&apos;s run settings are invalid: %1</source>
        <translation>Nichts wird ausgeführt, solange die Ausführungseinstellungen der Einrichtstudie ungültig sind: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupResultsView</name>
    <message>
        <location filename="../widgets/setup/setupresultsview.cpp" line="+37"/>
        <source>machine point</source>
        <translation>Maschinenpunkt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work offset</source>
        <translation>Nullpunktverschiebung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tool length</source>
        <translation>Werkzeuglänge</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Export Q-DAS &amp;DFQ…</source>
        <translation>Q-DAS-&amp;DFQ exportieren…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Setup datum</source>
        <translation>Einrichtdatum</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Register</source>
        <translation>Register</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Correction (mm)</source>
        <translation>Korrektur (mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Increment to add to the register along the model&apos;s axis (see the export headers)</source>
        <translation>Inkrement, das entlang der Modellachse zum Register addiert wird (siehe Exportköpfe)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Export the corrections:</source>
        <translation>Korrekturen exportieren:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Fanuc…</source>
        <translation>&amp;Fanuc…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Heidenhain…</source>
        <translation>&amp;Heidenhain…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Siemens…</source>
        <translation>&amp;Siemens…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;CSV…</source>
        <translation>&amp;CSV…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Update HEIDENHAIN &amp;table…</source>
        <translation>HEIDENHAIN-&amp;Tabelle aktualisieren…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Add the corrections to the control&apos;s current preset table (.PR) or tool table (.T), saved from the control, and write the result to a new file for import; the rows are the registers of the model</source>
        <translation>Die Korrekturen zur aktuellen Bezugspunkttabelle (.PR) oder Werkzeugtabelle (.T) der Steuerung addieren, die von der Steuerung gespeichert wurde, und das Ergebnis zum Einlesen in eine neue Datei schreiben; die Zeilen sind die Register des Modells</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Tool re&amp;gister:</source>
        <translation>Werkzeug&amp;register:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>wear (DL)</source>
        <translation>Verschleiß (DL)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>geometry (L)</source>
        <translation>Geometrie (L)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The register the tool-length corrections go to in every export: the wear (DL, Fanuc H wear) or the geometry (L)</source>
        <translation>Das Register, in das die Werkzeuglängenkorrekturen bei jedem Export gehen: Verschleiß (DL, Fanuc H-Verschleiß) oder Geometrie (L)</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+252"/>
        <source>There is no measurement report to export</source>
        <translation>Es gibt keinen Messbericht zum Exportieren</translation>
    </message>
    <message>
        <location line="-222"/>
        <source>No result yet: choose a method and press Run (Ctrl+R).</source>
        <translation>Noch kein Ergebnis: Methode wählen und Ausführen drücken (Strg+R).</translation>
    </message>
    <message numerus="yes">
        <location line="+44"/>
        <source>%n LP / MILP solver call(s)</source>
        <translation>
            <numerusform>%n LP-/MILP-Solver-Aufruf</numerusform>
            <numerusform>%n LP-/MILP-Solver-Aufrufe</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n solution(s) evaluated</source>
        <translation>
            <numerusform>%n Lösung bewertet</numerusform>
            <numerusform>%n Lösungen bewertet</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: f1 %2 → %3 mm (bonus %4 mm), |x| = f2 %5 mm, f %6; %7 in %8 ms.</source>
        <translation>%1: f1 %2 → %3 mm (Bonus %4 mm), |x| = f2 %5 mm, f %6; %7 in %8 ms.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>f1 proven optimal on the grid</source>
        <translation>f1 auf dem Raster nachweislich optimal</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f1 NOT proven optimal</source>
        <translation>f1 NICHT nachweislich optimal</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>|x| proven minimal.</source>
        <translation>|x| nachweislich minimal.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>|x| not proven minimal.</source>
        <translation>|x| nicht nachweislich minimal.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gap to the exact optimum: f1 %1 mm, f2 %2 mm.</source>
        <translation>Abstand zum exakten Optimum: f1 %1 mm, f2 %2 mm.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(cancelled: best so far)</source>
        <translation>(abgebrochen: bisher beste)</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Parts of the report in tolerance: %1 of %2 before, %3 of %2 after the correction; parts rescued: %4.</source>
        <translation>Werkstücke des Berichts in Toleranz: %1 von %2 vor, %3 von %2 nach der Korrektur; gerettete Werkstücke: %4.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Parts that would leave the tolerance: %1.</source>
        <translation>Werkstücke, die die Toleranz verlassen würden: %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+40"/>
        <source>There are no corrections to export yet.</source>
        <translation>Es gibt noch keine Korrekturen zum Exportieren.</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>Export corrections</source>
        <translation>Korrekturen exportieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot export the corrections</source>
        <translation>Die Korrekturen können nicht exportiert werden</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The updated table must go to a new file: %1 is the table read from the control.</source>
        <translation>Die aktualisierte Tabelle muss in eine neue Datei: %1 ist die von der Steuerung gelesene Tabelle.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The control&apos;s current table (saved from the control)</source>
        <translation>Aktuelle Tabelle der Steuerung (von der Steuerung gespeichert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HEIDENHAIN preset and tool tables (*.PR *.pr *.T *.t);;All files (*)</source>
        <translation>HEIDENHAIN-Bezugspunkt- und Werkzeugtabellen (*.PR *.pr *.T *.t);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Write the updated table to</source>
        <translation>Aktualisierte Tabelle schreiben nach</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot update the HEIDENHAIN table</source>
        <translation>Die HEIDENHAIN-Tabelle kann nicht aktualisiert werden</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 written to %2. Cells updated: %3.</source>
        <translation>%1 nach %2 geschrieben. Aktualisierte Zellen: %3.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not in this table: %1.</source>
        <translation>Nicht in dieser Tabelle: %1.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import it with no NC program running, then activate the preset again or call the tool again.</source>
        <translation>Einlesen, während kein NC-Programm läuft, dann den Bezugspunkt erneut aktivieren bzw. das Werkzeug erneut aufrufen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HEIDENHAIN table updated</source>
        <translation>HEIDENHAIN-Tabelle aktualisiert</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Write the measured features of the report as a Q-DAS DFQ file (one characteristic per measured dimension)</source>
        <translation>Die gemessenen Merkmale des Berichts als Q-DAS-DFQ-Datei schreiben (ein Merkmal je gemessenem Maß)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>There is no measurement report to export.</source>
        <translation>Es gibt keinen Messbericht zum Exportieren.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export Q-DAS DFQ</source>
        <translation>Q-DAS-DFQ exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Q-DAS DFQ files (*.dfq);;All files (*)</source>
        <translation>Q-DAS-DFQ-Dateien (*.dfq);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot export the DFQ file</source>
        <translation>Die DFQ-Datei kann nicht exportiert werden</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupValidationView</name>
    <message>
        <location filename="../widgets/setup/setupvalidationview.cpp" line="+78"/>
        <source>Simulated measurement sets N (the paper: 100)</source>
        <translation>Simulierte Messreihen N (Veröffentlichung: 100)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Trials M of every method on every set (the paper: 10)</source>
        <translation>Versuche M jeder Methode auf jeder Messreihe (Veröffentlichung: 10)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> solutions</source>
        <translation> Lösungen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Weight of the setup-data errors, Eq. 12: E = w1 (1 − 2r)</source>
        <translation>Gewicht der Einrichtdatenfehler, Gl. 12: E = w1 (1 − 2r)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Weight of the random errors, Eq. 13: E = w2 (1 − 2r)</source>
        <translation>Gewicht der zufälligen Fehler, Gl. 13: E = w2 (1 − 2r)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Run &amp;validation</source>
        <translation>Validierung aus&amp;führen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="-49"/>
        <source>The paper&apos;s statistical validation: simulated measurement sets with setup-data and random errors (Eq. 12–13), each corrected by the exact method and by M trials of the chosen metaheuristics; the sets sorted by their budget before correction (Fig. 18).</source>
        <translation>Die statistische Validierung der Veröffentlichung: simulierte Messreihen mit Einrichtdaten- und Zufallsfehlern (Gl. 12–13), jeweils korrigiert mit der exakten Methode und mit M Versuchen der gewählten Metaheuristiken; die Reihen sortiert nach ihrem Budget vor der Korrektur (Abb. 18).</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>Measurement sets N:</source>
        <translation>Messreihen N:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trials per set M:</source>
        <translation>Versuche je Reihe M:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Budget per trial:</source>
        <translation>Budget je Versuch:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>w1 (setup data):</source>
        <translation>w1 (Einrichtdaten):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>w2 (random):</source>
        <translation>w2 (zufällig):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Seed:</source>
        <translation>Startwert:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Methods:</source>
        <translation>Methoden:</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>Choose at least one method.</source>
        <translation>Wählen Sie mindestens eine Methode.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Running %1 sets x %2 trials…</source>
        <translation>%1 Reihen x %2 Versuche laufen…</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>The validation failed: %1</source>
        <translation>Die Validierung ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 sets%2: f1 before correction from %3 to %4 mm.</source>
        <translation>%1 Reihen%2: f1 vor der Korrektur von %3 bis %4 mm.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (cancelled)</source>
        <translation> (abgebrochen)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The paper&apos;s range %1 to %2 mm is consistent with the simulator (its minimum lies in %3 to %4 mm, its maximum in %5 to %6 mm over 100 sets, 98 % bands).</source>
        <translation>Der Bereich des Artikels, %1 bis %2 mm, ist mit dem Simulator vereinbar (sein Minimum liegt in %3 bis %4 mm, sein Maximum in %5 bis %6 mm über 100 Sätze, 98-%-Bänder).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NOT consistent: the paper&apos;s range %1 to %2 mm lies outside the simulator&apos;s bands (minimum %3 to %4 mm, maximum %5 to %6 mm over 100 sets, 98 %).</source>
        <translation>NICHT vereinbar: der Bereich des Artikels, %1 bis %2 mm, liegt außerhalb der Bänder des Simulators (Minimum %3 bis %4 mm, Maximum %5 bis %6 mm über 100 Sätze, 98 %).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The paper&apos;s range (%1 to %2 mm) is for w1 = 0.03 and w2 = 0.02 mm: not compared.</source>
        <translation>Der Bereich des Artikels (%1 bis %2 mm) gilt für w1 = 0,03 und w2 = 0,02 mm: nicht verglichen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: mean gap to the exact f1 %2 mm; %3 of %4 trials within one grid step.</source>
        <translation>%1: mittlerer Abstand zum exakten f1 %2 mm; %3 von %4 Versuchen innerhalb eines Rasterschritts.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Share of the setup data in the dimension error, estimated from the sets: %1 % of the weights (configured %2 %), %3 % of the variance.</source>
        <translation>Anteil der Einrichtdaten am Maßfehler, aus den Sätzen geschätzt: %1 % der Gewichte (eingestellt %2 %), %3 % der Varianz.</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>In the project&apos;s measurements (%n part(s)): %1 % of the weights, %2 % of the variance.</source>
        <translation>
            <numerusform>In den Messungen des Projekts (%n Teil): %1 % der Gewichte, %2 % der Varianz.</numerusform>
            <numerusform>In den Messungen des Projekts (%n Teile): %1 % der Gewichte, %2 % der Varianz.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The setup share of the measurements cannot be estimated: %1</source>
        <translation>Der Anteil der Einrichtdaten in den Messungen kann nicht geschätzt werden: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::SpcView</name>
    <message>
        <location filename="../widgets/kinematics/kinematicsviews.cpp" line="+135"/>
        <source>index</source>
        <translation>Kenngröße</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>No SPC series yet.</source>
        <translation>Noch keine SPC-Reihe.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Histogram of %1 (%2 values)</source>
        <translation>Histogramm von %1 (%2 Werte)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>feature</source>
        <translation>Merkmal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroups × size</source>
        <translation>Untergruppen × Umfang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> (%1 left out)</source>
        <translation> (%1 ausgelassen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>in control</source>
        <translation>beherrscht</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no: %1 X-bar, %2 R points beyond limits</source>
        <translation>nein: %1 x̄-, %2 R-Punkte außerhalb der Grenzen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Nelson rules</source>
        <translation>Nelson-Regeln</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A2 / D3 / D4</source>
        <translation>A2 / D3 / D4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>X-bar CL / UCL / LCL</source>
        <translation>x̄ CL / UCL / LCL</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>R CL / UCL / LCL</source>
        <translation>R CL / UCL / LCL</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>σ within (R̄/d2)</source>
        <translation>σ innerhalb (R̄/d2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>LSL / USL</source>
        <translation>LSL / USL</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cp (Eq. 16)</source>
        <translation>Cp (Gl. 16)</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <source>— (no limits)</source>
        <translation>— (keine Grenzen)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cpk</source>
        <translation>Cpk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>natural tolerance (Eq. 17)</source>
        <translation>natürliche Toleranz (Gl. 17)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+5"/>
        <source>systematic error (Eq. 20)</source>
        <translation>systematischer Fehler (Gl. 20)</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>%1%2 ± %3 (%4)</source>
        <translation>%1%2 ± %3 (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>significant</source>
        <translation>signifikant</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not significant</source>
        <translation>nicht signifikant</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>— (no nominal)</source>
        <translation>— (kein Nennwert)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>regression offset angle</source>
        <translation>Versatzwinkel der Regression</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1° (slope %2%3 per sample, r² %4)</source>
        <translation>%1° (Steigung %2%3 je Probe, r² %4)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>compensation</source>
        <translation>Kompensation</translation>
    </message>
</context>
<context>
    <name>metrofit::StoredResult</name>
    <message>
        <location filename="../widgets/document/storedresulttext.cpp" line="+11"/>
        <source>at an unknown time</source>
        <translation>zu unbekannter Zeit</translation>
    </message>
</context>
<context>
    <name>metrofit::StudyActions</name>
    <message>
        <location filename="../app/gui/studyactions.cpp" line="+52"/>
        <source>&amp;Run</source>
        <translation>A&amp;usführen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Run the study</source>
        <translation>Studie a&amp;usführen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Runs the method of the page shown (its Run button, Ctrl+R)</source>
        <translation>Führt die Methode der angezeigten Seite aus (ihre Schaltfläche „Ausführen“, Strg+R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Cancel the run</source>
        <translation>Ausführung a&amp;bbrechen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stops the running method of the page shown</source>
        <translation>Hält die laufende Methode der angezeigten Seite an</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Nothing to run on this page</source>
        <translation>Auf dieser Seite gibt es nichts auszuführen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Nothing is running</source>
        <translation>Es läuft nichts</translation>
    </message>
</context>
<context>
    <name>metrofit::TableCopy</name>
    <message>
        <location filename="../widgets/common/tablecopy.cpp" line="+88"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Copy the selected cells with their column headers, tab-separated</source>
        <translation>Die ausgewählten Zellen mit ihren Spaltenüberschriften kopieren, durch Tabulatoren getrennt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Select &amp;all</source>
        <translation>&amp;Alles auswählen</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalCharts</name>
    <message>
        <location filename="../widgets/thermal/thermalcharts.cpp" line="+55"/>
        <source>temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacement</source>
        <translation>Verlagerung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>strain</source>
        <translation>Dehnung</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+17"/>
        <source>speed</source>
        <translation>Drehzahl</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>temperatures</source>
        <translation>Temperaturen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacements</source>
        <translation>Verlagerungen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>strains</source>
        <translation>Dehnungen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>other channels</source>
        <translation>weitere Kanäle</translation>
    </message>
    <message>
        <location line="+92"/>
        <location line="+113"/>
        <source>feed speed</source>
        <translation>Vorschubgeschwindigkeit</translation>
    </message>
    <message>
        <location line="-112"/>
        <location line="+70"/>
        <location line="+43"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>time (h)</source>
        <translation>Zeit (h)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time (min)</source>
        <translation>Zeit (min)</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>heating</source>
        <translation>Erwärmung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cooling</source>
        <translation>Abkühlung</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalHysteresisView</name>
    <message>
        <location filename="../widgets/thermal/thermalhysteresisview.cpp" line="+187"/>
        <source>loop area in %1 × %2</source>
        <translation>Schleifenfläche in %1 × %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the sensor lags the displacement</source>
        <translation>der Sensor eilt der Verlagerung nach</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the displacement lags the sensor</source>
        <translation>die Verlagerung eilt dem Sensor nach</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Sensor plotted against the displacement, or all sensors side by side</source>
        <translation>Sensor über der Verlagerung aufgetragen oder alle Sensoren nebeneinander</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>sensor</source>
        <translation>Sensor</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>loop area</source>
        <translation>Schleifenfläche</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>loop / ranges</source>
        <translation>Schleife / Spannweiten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lag τ (min)</source>
        <translation>Verzug τ (min)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R² lag</source>
        <translation>R² Verzug</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R² static</source>
        <translation>R² statisch</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Area enclosed by the trajectory (shoelace formula), sensor unit × displacement unit</source>
        <translation>Von der Trajektorie eingeschlossene Fläche (Gaußsche Trapezformel), Sensoreinheit × Verlagerungseinheit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Loop area divided by the product of the two ranges: 0 for a line, 0.785 for a circle</source>
        <translation>Schleifenfläche geteilt durch das Produkt der beiden Spannweiten: 0 für eine Linie, 0.785 für einen Kreis</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Time constant of a first-order lag between sensor and displacement; &gt; 0: the sensor lags</source>
        <translation>Zeitkonstante eines Verzögerungsglieds erster Ordnung zwischen Sensor und Verlagerung; &gt; 0: der Sensor eilt nach</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>&amp;Sensor:</source>
        <translation>&amp;Sensor:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Loop area and lag per sensor</source>
        <translation>Schleifenfläche und Verzug je Sensor</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Analysing the hysteresis of %1…</source>
        <translation>Hysterese von %1 wird analysiert…</translation>
    </message>
    <message>
        <location line="-179"/>
        <source>All sensors</source>
        <translation>Alle Sensoren</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No hysteresis analysis for this log:
%1</source>
        <translation>Keine Hystereseanalyse für dieses Protokoll:
%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Target %1: %2 heating rows, %3 cooling rows (the target&apos;s change grows or shrinks).</source>
        <translation>Zielgröße %1: %2 Zeilen Erwärmung, %3 Zeilen Abkühlung (die Änderung der Zielgröße wächst bzw. schrumpft).</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalModelCharts</name>
    <message>
        <location filename="../widgets/thermal/thermalmodelcharts.cpp" line="+70"/>
        <source>time (h)</source>
        <translation>Zeit (h)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time (min)</source>
        <translation>Zeit (min)</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>held out</source>
        <translation>Testdaten</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>fit | held-out boundary</source>
        <translation>Grenze Anpassung | Test</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1: not fitted</source>
        <translation>%1: nicht angepasst</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>%1: lag %2 min</source>
        <translation>%1: Verzug %2 min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 against %2: lag %3 min, loop %4</source>
        <translation>%1 über %2: Verzug %3 min, Schleife %4</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>heating</source>
        <translation>Erwärmung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cooling</source>
        <translation>Abkühlung</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+47"/>
        <source>%1 (off scale)</source>
        <translation>%1 (außerhalb)</translation>
    </message>
    <message>
        <location line="-23"/>
        <source>residual</source>
        <translation>Rest</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>measured (combined test)</source>
        <translation>gemessen (kombinierter Test)</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>module %1</source>
        <translation>Modul %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>modules, summed</source>
        <translation>Module, summiert</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>PSO iteration</source>
        <translation>PSO-Iteration</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>best fitness</source>
        <translation>beste Fitness</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalModelView</name>
    <message>
        <location filename="../widgets/thermal/thermalmodelview.cpp" line="+77"/>
        <source>%1 → %2%3</source>
        <translation>%1 → %2%3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>used by %1 (held-out error %2)</source>
        <translation>verwendet von %1 (Fehler auf den Testdaten %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not used by %1 (held-out error would rise: %2)</source>
        <translation>nicht verwendet von %1 (Fehler auf den Testdaten würde steigen: %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not used by %1 (held-out error would not fall: %2)</source>
        <translation>nicht verwendet von %1 (Fehler auf den Testdaten würde nicht sinken: %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Applied effects %1: %2.</source>
        <translation>Übernommene Effekte %1: %2.</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>Applied effects %1: Train (Ctrl+R) fits each model with and without them and keeps the lower held-out error.</source>
        <translation>Übernommene Effekte %1: Trainieren (Strg+R) passt jedes Modell mit und ohne sie an und behält den kleineren Fehler auf den Testdaten.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Effects added with Apply on the Diagnosis page (lagged inputs, extra input columns, a drift term, generic effects as the curve, step or levels the diagnosis fitted). Each model is fitted with the declared inputs and with the effects (same seed) and keeps the variant with the lower held-out error: an effect never makes a model worse on the held-out rows. Undo the Apply to fit the declared model only.</source>
        <translation>Mit „Ins Modell übernehmen“ auf der Seite „Diagnose“ hinzugefügte Effekte (verzögerte Eingänge, zusätzliche Eingangsspalten, ein Driftterm, generische Effekte als die Kurve, Stufe oder Niveaus, die die Diagnose angepasst hat). Jedes Modell wird mit den deklarierten Eingängen und mit den Effekten angepasst (gleicher Startwert) und behält die Variante mit dem kleineren Fehler auf den Testdaten: Ein Effekt macht ein Modell auf den Testzeilen nie schlechter. Machen Sie die Übernahme rückgängig, um nur das deklarierte Modell anzupassen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Applied effects cannot be used: %1</source>
        <translation>Übernommene Effekte können nicht verwendet werden: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>fitness</source>
        <translation>Fitness</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Best Eq. 2.9 fitness (sum of squared residuals%1) per PSO iteration</source>
        <translation>Beste Fitness nach Gl. 2.9 (Summe der quadrierten Residuen%1) je PSO-Iteration</translation>
    </message>
    <message>
        <location line="+39"/>
        <location line="+133"/>
        <source>not fitted: %1</source>
        <translation>nicht angepasst: %1</translation>
    </message>
    <message>
        <location line="-123"/>
        <source>fit (%1)</source>
        <translation>Anpassung (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>held out (%1)</source>
        <translation>Testdaten (%1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+120"/>
        <source>diverges</source>
        <translation>divergiert</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Least squares gave an unstable GMC(1,N): b1 = %1 ≤ 0; its output grows without bound on the held-out rows</source>
        <translation>Die kleinsten Quadrate ergaben ein instabiles GMC(1,N): b1 = %1 ≤ 0; seine Ausgabe wächst auf den Testdaten unbeschränkt</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+130"/>
        <location line="+151"/>
        <source>model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <location line="-281"/>
        <location line="+281"/>
        <source>rows</source>
        <translation>Zeilen</translation>
    </message>
    <message>
        <location line="-280"/>
        <location line="+280"/>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <location line="-280"/>
        <location line="+280"/>
        <source>RMSE</source>
        <translation>RMSE</translation>
    </message>
    <message>
        <location line="-279"/>
        <location line="+130"/>
        <location line="+149"/>
        <source>E</source>
        <translation>E</translation>
    </message>
    <message>
        <location line="-279"/>
        <location line="+279"/>
        <source>band</source>
        <translation>Band</translation>
    </message>
    <message>
        <location line="-278"/>
        <location line="+278"/>
        <source>verdict</source>
        <translation>Urteil</translation>
    </message>
    <message>
        <location line="-270"/>
        <source>%1 not fitted: %2.</source>
        <translation>%1 nicht angepasst: %2.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 %2 s</source>
        <translation>%1 %2 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> (unstable: b1 ≤ 0)</source>
        <translation> (instabil: b1 ≤ 0)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Best usable model: %1.</source>
        <translation>Bestes verwendbares Modell: %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No model is usable for compensation: record a longer test or add the inputs the diagnosis finds.</source>
        <translation>Kein Modell taugt zur Kompensation: Zeichnen Sie einen längeren Test auf oder nehmen Sie die Eingänge auf, die die Diagnose findet.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 fit rows, %2 held out; %3.</source>
        <translation>%1 Zeilen zur Anpassung, %2 Testdaten; %3.</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>modules, summed (distributed lag)</source>
        <translation>Module, summiert (verteilte Verzögerung)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 (inputs %2) contributes up to %3 %4</source>
        <translation>%1 (Eingänge %2) trägt bis zu %3 %4 bei</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Module by module, each identified on its own test: %1.</source>
        <translation>Modul für Modul, jedes an seinem eigenen Test identifiziert: %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Module by module: not identified (%1).</source>
        <translation>Modul für Modul: nicht identifiziert (%1).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>error → band (%1)</source>
        <translation>Fehler → Band (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>less (peak, %)</source>
        <translation>weniger (Spitze, %)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMSE (%1)</source>
        <translation>RMSE (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>less (RMS, %)</source>
        <translation>weniger (RMS, %)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>not identified</source>
        <translation>nicht identifiziert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Identify again…</source>
        <translation>Erneut identifizieren…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Identify this module again on another test of its drive (a thermal log of the project); the other modules keep their models</source>
        <translation>Dieses Modul an einem anderen Test seines Antriebs (einem Thermoprotokoll des Projekts) erneut identifizieren; die anderen Module behalten ihre Modelle</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>module</source>
        <translation>Modul</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>identified on</source>
        <translation>identifiziert an</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inputs</source>
        <translation>Eingänge</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>contribution (peak)</source>
        <translation>Beitrag (Spitze)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: %p%</source>
        <translation>%1: %p%</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The column the models predict (the thermal error)</source>
        <translation>Die Spalte, die die Modelle vorhersagen (der thermische Fehler)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Sensor columns the models take as inputs</source>
        <translation>Sensorspalten, die die Modelle als Eingänge verwenden</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The first fraction of the rows fits the models; the rest is held out</source>
        <translation>Der erste Anteil der Zeilen dient der Anpassung der Modelle; der Rest sind Testdaten</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Seed of the PSO swarm and of the MLP&apos;s initial weights (same seed, same result)</source>
        <translation>Startwert des PSO-Schwarms und der Anfangsgewichte des MLP (gleicher Startwert, gleiches Ergebnis)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Train</source>
        <translation>&amp;Trainieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fit GNNMCI(1,N) (PSO), GMC(1,N) (least squares) and the MLP (Levenberg-Marquardt) (Ctrl+R)</source>
        <translation>GNNMCI(1,N) (PSO), GMC(1,N) (kleinste Quadrate) und das MLP (Levenberg-Marquardt) anpassen (Strg+R)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+99"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="-95"/>
        <source>Stop the training (Esc)</source>
        <translation>Das Training anhalten (Esc)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Best fitness of the GNNMCI(1,N) swarm (Eq. 2.9) per PSO iteration</source>
        <translation>Beste Fitness des GNNMCI(1,N)-Schwarms (Gl. 2.9) je PSO-Iteration</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>T&amp;arget:</source>
        <translation>&amp;Zielgröße:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Train &amp;fraction:</source>
        <translation>Trainingsa&amp;nteil:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;eed:</source>
        <translation>S&amp;tartwert:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Inputs:</source>
        <translation>&amp;Eingänge:</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Correlation coefficient of measured and predicted</source>
        <translation>Korrelationskoeffizient zwischen gemessen und vorhergesagt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Root mean square of the residual, in the target&apos;s unit</source>
        <translation>Quadratischer Mittelwert des Residuums, in der Einheit der Zielgröße</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nash-Sutcliffe efficiency coefficient (1: perfect)</source>
        <translation>Nash-Sutcliffe-Effizienzkoeffizient (1: perfekt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest |residual|, in the target&apos;s unit</source>
        <translation>Größtes |Residuum|, in der Einheit der Zielgröße</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Usable for compensation when on the held-out rows it does not diverge, E ≥ %1 and R ≥ %2</source>
        <translation>Zur Kompensation verwendbar, wenn es auf den zurückgehaltenen Zeilen nicht divergiert, E ≥ %1 und R ≥ %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modular models (Section 4.3)</source>
        <translation>Modulare Modelle (Abschnitt 4.3)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Save module models…</source>
        <translation>Modulmodelle speichern…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write each module&apos;s fitted model to a folder as NAME.json (the files of metrofit-cli thermal modular --save-modules)</source>
        <translation>Das angepasste Modell jedes Moduls als NAME.json in einen Ordner schreiben (die Dateien von metrofit-cli thermal modular --save-modules)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop identifying the module; the modules shown stay</source>
        <translation>Die Identifikation des Moduls anhalten; die angezeigten Module bleiben</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Performance indices (Table 4)</source>
        <translation>Gütekennzahlen (Tabelle 4)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Comparison</source>
        <translation>Vergleich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modular (Z + C → combined)</source>
        <translation>Modular (Z + C → kombiniert)</translation>
    </message>
    <message>
        <location line="+35"/>
        <location line="+118"/>
        <source>Training failed: %1</source>
        <translation>Das Training ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="-132"/>
        <source>Training cancelled after %1 PSO iterations; the results shown are the previous ones.</source>
        <translation>Training nach %1 PSO-Iterationen abgebrochen; die angezeigten Ergebnisse sind die vorherigen.</translation>
    </message>
    <message>
        <location line="-337"/>
        <source>not fitted</source>
        <translation>nicht angepasst</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;b&gt;Modular case:&lt;/b&gt; GNNMCI(1,N) fitted on the Z and C tests reduces the combined test&apos;s error by %1 (GMC(1,N) %2, MLP %3).</source>
        <translation>&lt;b&gt;Modularer Fall:&lt;/b&gt; GNNMCI(1,N), angepasst an den Z- und C-Tests, verringert den Fehler des kombinierten Tests um %1 (GMC(1,N) %2, MLP %3).</translation>
    </message>
    <message>
        <location line="+356"/>
        <source>Settings changed: Train (Ctrl+R) to update the results.</source>
        <translation>Einstellungen geändert: Trainieren (Strg+R), um die Ergebnisse zu aktualisieren.</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Not trained yet: Train (Ctrl+R) fits the three models.</source>
        <translation>Noch nicht trainiert: Trainieren (Strg+R) passt die drei Modelle an.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Applied effects changed: Train (Ctrl+R) to update the results.</source>
        <translation>Übernommene Effekte geändert: Trainieren (Strg+R), um die Ergebnisse zu aktualisieren.</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+23"/>
        <source>Choose at least one input.</source>
        <translation>Wählen Sie mindestens einen Eingang.</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Training…</source>
        <translation>Training läuft…</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalPage</name>
    <message>
        <location filename="../app/gui/thermalpage.cpp" line="+128"/>
        <source>Export compensation…</source>
        <translation>Kompensation exportieren…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write a trained model in a form the machine control runs: an IEC 61131-3 function block, SINUMERIK or Heidenhain data, ISG axis parameters or a table (metrofit-cli thermal export)</source>
        <translation>Ein trainiertes Modell in einer Form schreiben, die die Maschinensteuerung ausführt: ein IEC-61131-3-Funktionsbaustein, SINUMERIK- oder Heidenhain-Daten, ISG-Achsparameter oder eine Tabelle (metrofit-cli thermal export)</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+18"/>
        <location line="+6"/>
        <location line="+10"/>
        <location line="+5"/>
        <location line="+9"/>
        <location line="+7"/>
        <source>Export compensation</source>
        <translation>Kompensation exportieren</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>Train the models first (Models tab): the export writes a trained model.</source>
        <translation>Zuerst die Modelle trainieren (Reiter Modelle): der Export schreibt ein trainiertes Modell.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (held-out RMSE %2)</source>
        <translation>%1 (RMSE der Testdaten %2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No trained model can be exported (a model that takes the applied effects&apos; columns cannot: the control does not have them).</source>
        <translation>Kein trainiertes Modell kann exportiert werden (ein Modell mit den Spalten der übernommenen Effekte nicht: die Steuerung hat sie nicht).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Model:</source>
        <translation>Modell:</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Form (st: IEC 61131-3 function block; siemens, heidenhain, isg: the control&apos;s temperature compensation; csv: a table):</source>
        <translation>Form (st: IEC-61131-3-Funktionsbaustein; siemens, heidenhain, isg: die Temperaturkompensation der Steuerung; csv: eine Tabelle):</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot export the compensation: %1</source>
        <translation>Die Kompensation kann nicht exportiert werden: %1</translation>
    </message>
    <message>
        <location line="-91"/>
        <source>T&amp;rend</source>
        <translation>&amp;Verlauf</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Hysteresis</source>
        <translation>H&amp;ysterese</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Models</source>
        <translation>&amp;Modelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temperatures, strains and displacement against time</source>
        <translation>Temperaturen, Dehnungen und Verlagerung über der Zeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Displacement against each sensor over heating and cooling</source>
        <translation>Verlagerung über jedem Sensor während Erwärmung und Abkühlung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNNMCI(1,N), GMC(1,N) and MLP fitted and compared (Table 4)</source>
        <translation>GNNMCI(1,N), GMC(1,N) und MLP angepasst und verglichen (Tabelle 4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Thermal log:</source>
        <translation>&amp;Thermoprotokoll:</translation>
    </message>
    <message>
        <location line="+127"/>
        <source>The module could not be identified again: %1</source>
        <translation>Das Modul konnte nicht erneut identifiziert werden: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cancelled: the modules shown are unchanged.</source>
        <translation>Abgebrochen: die angezeigten Module sind unverändert.</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>studies.thermal.train_fraction: %1 cannot be set on the page (it takes 0.01 to 0.99 in steps of 0.01)</source>
        <translation>studies.thermal.train_fraction: %1 kann auf der Seite nicht eingestellt werden (sie nimmt 0,01 bis 0,99 in Schritten von 0,01)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>studies.thermal.seed: %1 is larger than the page can use (at most %2)</source>
        <translation>studies.thermal.seed: %1 ist größer, als die Seite verwenden kann (höchstens %2)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The thermal study&apos;s settings are invalid, nothing is fitted until they are corrected (Undo, or the project file):
%1</source>
        <translation>Die Einstellungen der Thermikstudie sind ungültig; nichts wird angepasst, bis sie korrigiert sind (Rückgängig oder die Projektdatei):
%1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>This project has no thermal log. Add a dataset of kind &quot;thermal_log&quot; to the project file (a time column, sensor columns and the displacement).</source>
        <translation>Dieses Projekt hat kein Thermoprotokoll. Fügen Sie der Projektdatei einen Datensatz der Art „thermal_log“ hinzu (eine Zeitspalte, Sensorspalten und die Verlagerung).</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 rows, %2 channels, %3 h.</source>
        <translation>%1 Zeilen, %2 Kanäle, %3 h.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Licence: %1.</source>
        <translation>Lizenz: %1.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Cannot show this thermal log:
%1</source>
        <translation>Dieses Thermoprotokoll kann nicht angezeigt werden:
%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Effects applied on the Diagnosis page belong to the log %1 (the one the diagnosis ran on); the models of this log do not include them.</source>
        <translation>Die auf der Seite „Diagnose“ übernommenen Effekte gehören zum Thermoprotokoll %1 (auf dem die Diagnose lief); die Modelle dieses Protokolls enthalten sie nicht.</translation>
    </message>
    <message>
        <location line="-185"/>
        <source>Choose the thermal log</source>
        <translation>Thermoprotokoll wählen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change the thermal target</source>
        <translation>Thermische Zielgröße ändern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change the thermal inputs</source>
        <translation>Thermische Eingänge ändern</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change the train fraction</source>
        <translation>Trainingsanteil ändern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change the training seed</source>
        <translation>Startwert des Trainings ändern</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change the thermal model settings</source>
        <translation>Einstellungen des thermischen Modells ändern</translation>
    </message>
    <message>
        <location line="+249"/>
        <source>The stored result (computed %1) is out of date: the model settings changed since. Not trained with these settings yet: Train (Ctrl+R).</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Modelleinstellungen haben sich seitdem geändert. Mit diesen Einstellungen noch nicht trainiert: Trainieren (Strg+R).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the data file changed since. Train (Ctrl+R) to fit the models on the data as it is now.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) ist veraltet: die Datendatei hat sich seitdem geändert. Trainieren (Strg+R), um die Modelle an die Daten in ihrem jetzigen Stand anzupassen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the data file cannot be read.</source>
        <translation>Das gespeicherte Ergebnis (berechnet %1) kann nicht geprüft werden: die Datendatei ist nicht lesbar.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not fitted</source>
        <translation>nicht angepasst</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no model usable for compensation</source>
        <translation>kein für die Kompensation verwendbares Modell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>best usable model %1 (held-out RMSE %2)</source>
        <translation>bestes verwendbares Modell %1 (RMSE zurückgehalten %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From the saved project, computed %1 with these settings on this data: %2. Held-out RMSE: %3. Train (Ctrl+R) to see the charts.</source>
        <translation>Aus dem gespeicherten Projekt, berechnet %1 mit diesen Einstellungen auf diesen Daten: %2. RMSE zurückgehalten: %3. Trainieren (Strg+R), um die Diagramme zu sehen.</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>Fitted on %1 and %2 together, predicting %3 (target %4; inputs %5; seed 1): GNNMCI(1,N) not fitted: %6</source>
        <translation>Gemeinsam an %1 und %2 angepasst, Vorhersage für %3 (Zielgröße %4; Eingänge %5; Startwert 1): GNNMCI(1,N) nicht angepasst: %6</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Modular case: %1</source>
        <translation>Modularer Fall: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The modules&apos; tests of the thermal study cannot be used (%1); the modules are identified on their own tests.</source>
        <translation>Die Tests der Module aus der thermischen Studie können nicht verwendet werden (%1); die Module werden an ihren eigenen Tests identifiziert.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Modules identified on %1; the others kept their models. The modules&apos; sum: RMSE %2%3 on %4.</source>
        <translation>Module an %1 identifiziert; die anderen haben ihre Modelle behalten. Summe der Module: RMSE %2%3 an %4.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the tests of the thermal study</source>
        <translation>den Tests der thermischen Studie</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Identify module %1 again on %2</source>
        <translation>Modul %1 an %2 erneut identifizieren</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Identifying…</source>
        <translation>Identifikation läuft…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Identifying on %1…</source>
        <translation>Identifikation an %1…</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Saved %1 to %2.</source>
        <translation>%1 in %2 gespeichert.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot save the module models: %1</source>
        <translation>Die Modulmodelle können nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Identify %1 again</source>
        <translation>%1 erneut identifizieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The test to identify module %1 on (a new test of its drive; now %2). The other modules keep their models.</source>
        <translation>Der Test, an dem Modul %1 identifiziert wird (ein neuer Test seines Antriebs; jetzt %2). Die anderen Module behalten ihre Modelle.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Save module models to</source>
        <translation>Modulmodelle speichern in</translation>
    </message>
    <message>
        <location line="-161"/>
        <source>Fitted on %1 and %2 together, predicting %3 (target %4; inputs %5; seed 1): GNNMCI(1,N) reduces the combined test&apos;s error by %6 %.</source>
        <translation>Gemeinsam an %1 und %2 angepasst, Vorhersage für %3 (Zielgröße %4; Eingänge %5; Startwert 1): GNNMCI(1,N) verringert den Fehler des kombinierten Tests um %6 %.</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalTrendView</name>
    <message>
        <location filename="../widgets/thermal/thermaltrendview.cpp" line="+125"/>
        <source>Channels shown in the chart: tick a group to show all of it</source>
        <translation>In der Grafik gezeigte Kanäle: eine angekreuzte Gruppe zeigt alle ihre Kanäle</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Channels</source>
        <translation>Kanäle</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Show or hide all %1</source>
        <translation>Alle %1 zeigen oder ausblenden</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalVerdict</name>
    <message>
        <location filename="../widgets/thermal/thermalverdict.cpp" line="+19"/>
        <source>usable</source>
        <translation>verwendbar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not usable</source>
        <translation>nicht verwendbar</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>its prediction diverges on the held-out rows</source>
        <translation>seine Vorhersage divergiert auf den zurückgehaltenen Zeilen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>E = %1 on the held-out rows, below %2: it predicts worse than the mean of the error</source>
        <translation>E = %1 auf den zurückgehaltenen Zeilen, unter %2: Es sagt schlechter voraus als der Mittelwert des Fehlers</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>R = %1 on the held-out rows, below %2: it hardly follows the error</source>
        <translation>R = %1 auf den zurückgehaltenen Zeilen, unter %2: Es folgt dem Fehler kaum</translation>
    </message>
</context>
<context>
    <name>metrofit::core</name>
    <message>
        <location filename="../widgets/diagnose/coretexts.cpp" line="+20"/>
        <source>n/a</source>
        <translation>k. A.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accepted: </source>
        <translation>übernommen: </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; passed, but %1 explains more</source>
        <translation>; bestanden, aber %1 erklärt mehr</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped by the observer after round %1</source>
        <translation>vom Beobachter nach Runde %1 angehalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time (min)</source>
        <translation>Zeit (min)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radial residual (mm)</source>
        <translation>radiales Residuum (mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>too few fit rows (%1) for %2 coefficients</source>
        <translation>zu wenige Anpassungszeilen (%1) für %2 Koeffizienten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>column &apos;%1&apos; is constant on the fit rows</source>
        <translation>Spalte „%1“ ist auf den Anpassungszeilen konstant</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the columns are linearly dependent on the fit rows</source>
        <translation>die Spalten sind auf den Anpassungszeilen linear abhängig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drift %1 +- %2%3/min</source>
        <translation>Drift %1 ± %2%3/min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>coefficient %1 +- %2%3 per unit</source>
        <translation>Koeffizient %1 ± %2%3 je Einheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>coefficient %1 +- %2%3 per %4</source>
        <translation>Koeffizient %1 ± %2%3 je %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tau %1 +- %2 min</source>
        <translation>τ %1 ± %2 min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tau %1 min</source>
        <translation>τ %1 min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = c0</source>
        <translation>%1 = c0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> + %1 %2</source>
        <translation> + %1 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared model (static, fitted on the first %1 of %2 rows): %3</source>
        <translation>deklariertes Modell (statisch, angepasst an die ersten %1 von %2 Zeilen): %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>noise level (first differences of the fit residual): %1%2</source>
        <translation>Rauschpegel (erste Differenzen des Anpassungsresiduums): %1%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not estimable: %1</source>
        <translation>nicht schätzbar: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>validation rmse %1 -&gt; %2%3 (%4), fit rmse %5 -&gt; %6%3, held-out rmse %7 -&gt; %8%3</source>
        <translation>rmse Validierung %1 → %2%3 (%4), rmse Anpassung %5 → %6%3, rmse Testdaten %7 → %8%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>validation rmse %1 -&gt; %2%3 (%4), fit rmse %5 -&gt; %6%3, held-out rmse %7 -&gt; %8%3, %9</source>
        <translation>rmse Validierung %1 → %2%3 (%4), rmse Anpassung %5 → %6%3, rmse Testdaten %7 → %8%3, %9</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; rejected: validation error worse</source>
        <translation>; abgelehnt: Validierungsfehler größer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: validation gain below %1 %</source>
        <translation>; abgelehnt: Gewinn in der Validierung unter %1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: explains %1%2, below %3 x the noise level %4%2</source>
        <translation>; abgelehnt: erklärt %1%2, weniger als das %3-Fache des Rauschpegels %4%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: no in-sample evidence (fit dBIC %1 &gt;= 0)</source>
        <translation>; abgelehnt: keine Evidenz in den Anpassungsdaten (dBIC der Anpassung %1 ≥ 0)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>accepted together with %1: validation rmse %2 -&gt; %3%4 (%5), fit rmse %6 -&gt; %7%4, held-out rmse %8 -&gt; %9%4, %10</source>
        <translation>übernommen zusammen mit %1: rmse Validierung %2 → %3%4 (%5), rmse Anpassung %6 → %7%4, rmse Testdaten %8 → %9%4, %10</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>; rejected: the validation folds cannot fit it</source>
        <translation>; abgelehnt: die Validierungsfolds können es nicht anpassen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>effects chosen on the fit rows by blocked forward validation (%1 folds, validation rmse %2%3); the held-out rows only report the error</source>
        <translation>Effekte auf den Anpassungszeilen durch blockweise Vorwärtsvalidierung gewählt (%1 Folds, rmse Validierung %2%3); die Testzeilen geben nur den Fehler an</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>%1 gross errors excluded before the fit (robust z above %2):</source>
        <translation>%1 grobe Fehler vor der Anpassung ausgeschlossen (robustes z über %2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> row %1 (%2%3)</source>
        <translation> Zeile %1 (%2%3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: the generic %1 validates better (%2 against %3%4)</source>
        <translation>; abgelehnt: der generische Effekt %1 validiert besser (%2 gegen %3%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; not taken: the generic %1 validates better (%2 against %3%4)</source>
        <translation>; nicht übernommen: der generische Effekt %1 validiert besser (%2 gegen %3%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: the residual still depends on %1 after it (%2, p = %3)</source>
        <translation>; abgelehnt: das Residuum hängt danach noch von %1 ab (%2, p = %3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: the fit rows do not determine tau (standard error above half of it)</source>
        <translation>; abgelehnt: die Anpassungszeilen bestimmen tau nicht (Standardfehler über der Hälfte)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>declared model %1 of %2 (fitted on the first %3 of %4 rows as thermal fit does; alone: fit rmse %5, held-out rmse %6%7); the loop fits the target on its prediction (coefficient %8) and the candidate effects</source>
        <translation>deklariertes Modell %1 von %2 (angepasst an die ersten %3 von %4 Zeilen wie bei thermal fit; allein: rmse Anpassung %5, rmse Testdaten %6%7); die Schleife passt die Zielgröße an seine Vorhersage (Koeffizient %8) und die Kandidateneffekte an</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>residual</source>
        <translation>Residuum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>residual (%1)</source>
        <translation>Residuum (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>path angle (deg)</source>
        <translation>Bahnwinkel (Grad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared model: origin (%1, %2) um, x axis %3 deg, y axis %4 deg, squareness %5 deg</source>
        <translation>deklariertes Modell: Ursprung (%1; %2) µm, x-Achse %3°, y-Achse %4°, Rechtwinkligkeit %5°</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not estimable: no period range to search on this path</source>
        <translation>nicht schätzbar: kein Periodenbereich, der auf dieser Bahn durchsucht werden kann</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not estimable from this path: its parameters are not observable together with the declared ones</source>
        <translation>aus dieser Bahn nicht schätzbar: seine Parameter sind zusammen mit den deklarierten nicht beobachtbar</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>backlash x %1 +- %2 um, y %3 +- %4 um</source>
        <translation>Umkehrspiel x %1 ± %2 µm, y %3 ± %4 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale x %1 +- %2 ppm, y %3 +- %4 ppm</source>
        <translation>Maßstab x %1 ± %2 ppm, y %3 ± %4 ppm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>servo lag tau %1 +- %2 s at %3 mm/min (%4 um)</source>
        <translation>Servoverzug τ %1 ± %2 s bei %3 mm/min (%4 µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cyclic on %1: period %2 +- %3 mm, amplitude %4 +- %5 um</source>
        <translation>zyklisch auf %1: Periode %2 ± %3 mm, Amplitude %4 ± %5 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rmse %1 -&gt; %2 um (%3 %), dBIC %4, %5</source>
        <translation>rmse %1 → %2 µm (%3 %), dBIC %4, %5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: dBIC above -%1</source>
        <translation>; abgelehnt: dBIC über -%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: rmse gain below %1 %</source>
        <translation>; abgelehnt: rmse-Gewinn unter %1 %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>declared model: constant errors of the %1 setup data through the relation graph, least squares over %2 rows of %3 parts; rank %4 of %5</source>
        <translation>deklariertes Modell: konstante Fehler der %1 Einrichtdaten über den Beziehungsgraphen, kleinste Quadrate über %2 Zeilen von %3 Werkstücken; Rang %4 von %5</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> (rank deficient: minimum-norm solution)</source>
        <translation> (rangdefizient: Lösung mit minimaler Norm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared fit (minimum norm), setup errors mm:</source>
        <translation>deklarierte Anpassung (minimale Norm), Einrichtfehler mm:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> %1=%2</source>
        <translation> %1=%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not identifiable: %1 (one part only?)</source>
        <translation>nicht identifizierbar: %1 (nur ein Werkstück?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not identifiable: %1 (time does not vary?)</source>
        <translation>nicht identifizierbar: %1 (Zeit ändert sich nicht?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 +- %2 mm/part (t = %3); </source>
        <translation>%1 ± %2 mm/Werkstück (t = %3); </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 +- %2 mm/min (t = %3); </source>
        <translation>%1 ± %2 mm/min (t = %3); </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part</source>
        <translation>Werkstück</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>apparent error of %1 (mm)</source>
        <translation>scheinbarer Fehler von %1 (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; preferred to %1 (its dBIC is %2 lower, below the threshold: the data cannot tell them apart)</source>
        <translation>; %1 vorgezogen (dessen dBIC ist um %2 niedriger, unter der Schwelle: die Daten können sie nicht unterscheiden)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>; indistinguishable from %1 with these data</source>
        <translation>; mit diesen Daten nicht von %1 zu unterscheiden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>distance from the centroid (mm)</source>
        <translation>Abstand vom Schwerpunkt (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deviation along the normal (mm)</source>
        <translation>Abweichung entlang der Normalen (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>surface</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>polar angle (deg)</source>
        <translation>Polarwinkel (Grad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = %2 +- %3</source>
        <translation>%1 = %2 ± %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, %1 = %2 +- %3</source>
        <translation>, %1 = %2 ± %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, %1 = %2</source>
        <translation>, %1 = %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared model: rigid posture p = R q + t fitted to %1, %2 points</source>
        <translation>deklariertes Modell: starre Lage p = R q + t, angepasst an %1, %2 Punkte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the deviations along the nominal normals</source>
        <translation>die Abweichungen entlang der Sollnormalen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the in-plane residuals (planar, position-only)</source>
        <translation>die Residuen in der Ebene (eben, nur Position)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the residual vectors (position-only)</source>
        <translation>die Residuenvektoren (nur Position)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared fit: rotation_deg [%1, %2, %3], translation_mm [%4, %5, %6]</source>
        <translation>deklarierte Anpassung: Rotation in Grad [%1; %2; %3], Translation in mm [%4; %5; %6]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not identifiable: %1 (the rigid posture explains it with these points)</source>
        <translation>nicht identifizierbar: %1 (die starre Lage erklärt es mit diesen Punkten)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1; %2</source>
        <translation>%1; %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; indistinguishable from %1 with these points</source>
        <translation>; mit diesen Punkten nicht von %1 zu unterscheiden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dBIC = %1 &lt; -%2, rmse %3 -&gt; %4 %5 (-%6 %)</source>
        <translation>dBIC = %1 &lt; -%2, rmse %3 → %4 %5 (-%6 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dBIC = %1 not below -%2, rmse %3 -&gt; %4 %5 (-%6 %)</source>
        <translation>dBIC = %1 nicht unter -%2, rmse %3 → %4 %5 (-%6 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dBIC = %1 &lt; -%2, rmse %3 -&gt; %4 %5 (-%6 %, below the relevant %7 %)</source>
        <translation>dBIC = %1 &lt; -%2, rmse %3 → %4 %5 (-%6 %, unter den relevanten %7 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dBIC = %1 &lt; -%2, rmse %3 -&gt; %4 %5 (-%6 %, below the relevant %7 %5)</source>
        <translation>dBIC = %1 &lt; -%2, rmse %3 → %4 %5 (-%6 %, unter den relevanten %7 %5)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>absorbed by the declared model</source>
        <translation>vom deklarierten Modell aufgenommen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its parameters are not separable with these data</source>
        <translation>seine Parameter sind mit diesen Daten nicht trennbar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>too few data for the parameters</source>
        <translation>zu wenige Daten für die Parameter</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linear</source>
        <translation>linear</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>smooth</source>
        <translation>glatt</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+98"/>
        <source>step</source>
        <translation>Sprung</translation>
    </message>
    <message>
        <location line="-97"/>
        <source>periodic</source>
        <translation>periodisch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per level</source>
        <translation>je Stufe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spike</source>
        <translation>Spitze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1</source>
        <translation>%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>too few observations (%1) to test the residual</source>
        <translation>zu wenige Beobachtungen (%1), um das Residuum zu testen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>white: no test finds structure at the %1 % family-wise level (%2 tests)</source>
        <translation>weiß: kein Test findet Struktur auf dem familienweisen Niveau von %1 % (%2 Tests)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not white: still depends on </source>
        <translation>nicht weiß: hängt noch ab von </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2, %3 % of the residual variance)</source>
        <translation>%1 (%2, %3 % der Residuenvarianz)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> and %1 more</source>
        <translation> und %1 weitere</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not white: serially correlated in %1 order (Ljung-Box p = %2)</source>
        <translation>nicht weiß: seriell korreliert in der Reihenfolge %1 (Ljung-Box p = %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 in %2, rms %3%4, range %5%4</source>
        <translation>%1 in %2, rms %3%4, Spannweite %5%4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, step %1%2 at %3</source>
        <translation>, Sprung %1%2 bei %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, strongest harmonic %1 (amplitude %2%3)</source>
        <translation>, stärkste Harmonische %1 (Amplitude %2%3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, period %1, amplitude %2%3</source>
        <translation>, Periode %1, Amplitude %2%3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 gross errors excluded before the fit (robust z above the outlier threshold):</source>
        <translation>%1 grobe Fehler vor der Anpassung ausgeschlossen (robustes z über der Ausreißerschwelle):</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> row %1 (%2 um)</source>
        <translation> Zeile %1 (%2 µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> row %1 (part %2, %3, %4 mm)</source>
        <translation> Zeile %1 (Werkstück %2, %3, %4 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> point %1 (row %2, %3 mm)</source>
        <translation> Punkt %1 (Zeile %2, %3 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; </source>
        <translation>; </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not identifiable: %1</source>
        <translation>nicht identifizierbar: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rejected: does not explain what it was chosen for; without it the generic effects explain the data as well (BIC %1 without, %2 with, needed %3 lower)</source>
        <translation>abgelehnt: erklärt nicht, wofür er gewählt wurde; ohne ihn erklären die generischen Effekte die Daten ebenso gut (BIC %1 ohne, %2 mit, nötig %3 niedriger)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>samples since an axis reversed (signed, log scale)</source>
        <translation>Abtastwerte seit einer Achsumkehr (mit Vorzeichen, logarithmisch)</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>data row</source>
        <translation>Datenzeile</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dimension</source>
        <translation>Maß</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>loop direction</source>
        <translation>Umlaufrichtung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>part number (%1)</source>
        <translation>Werkstücknummer (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position along surface %1 (mm)</source>
        <translation>Lage entlang der Fläche %1 (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>normal x</source>
        <translation>Normale x</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>normal y</source>
        <translation>Normale y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>normal z</source>
        <translation>Normale z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>x (mm)</source>
        <translation>x (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y (mm)</source>
        <translation>y (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>z (mm)</source>
        <translation>z (mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>converged</source>
        <translation>konvergiert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>budget exhausted</source>
        <translation>Budget erschöpft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>iteration limit</source>
        <translation>Iterationsgrenze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no nominal value given: nothing to compensate against</source>
        <translation>kein Nennwert angegeben: nichts, worauf kompensiert werden könnte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroup %1 beyond the X-bar limits</source>
        <translation>Untergruppe %1 außerhalb der x̄-Eingriffsgrenzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroups %1 beyond the X-bar limits</source>
        <translation>Untergruppen %1 außerhalb der x̄-Eingriffsgrenzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroup %1 beyond the R limits</source>
        <translation>Untergruppe %1 außerhalb der R-Eingriffsgrenzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroups %1 beyond the R limits</source>
        <translation>Untergruppen %1 außerhalb der R-Eingriffsgrenzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; subgroup %1 beyond the R limits</source>
        <translation>; Untergruppe %1 außerhalb der R-Eingriffsgrenzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; subgroups %1 beyond the R limits</source>
        <translation>; Untergruppen %1 außerhalb der R-Eingriffsgrenzen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not compensated: the process is out of control (%1); remove the special causes first, a correction would chase them</source>
        <translation>nicht kompensiert: der Prozess ist nicht beherrscht (%1); zuerst die besonderen Ursachen beseitigen, eine Korrektur würde ihnen nachlaufen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not compensated: the systematic error %1 is within its interval +-%2 (k = %3): random scatter, not a systematic error</source>
        <translation>nicht kompensiert: der systematische Fehler %1 liegt in seinem Intervall ±%2 (k = %3): zufällige Streuung, kein systematischer Fehler</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not compensated: the systematic error %1 is below the smallest correction %2</source>
        <translation>nicht kompensiert: der systematische Fehler %1 ist kleiner als die kleinste Korrektur %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>compensate %1: the systematic error (nominal - mean, Eq. 20) is beyond its interval +-%2 (k = %3) and the process is in control (%4 subgroups of %5)</source>
        <translation>kompensieren %1: der systematische Fehler (Nennwert − Mittelwert, Gl. 20) liegt außerhalb seines Intervalls ±%2 (k = %3) und der Prozess ist beherrscht (%4 Untergruppen zu %5)</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+11"/>
        <source>time constant</source>
        <translation>Zeitkonstante</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>coefficient</source>
        <translation>Koeffizient</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+12"/>
        <source>drift rate</source>
        <translation>Driftrate</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+2"/>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+2"/>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>period</source>
        <translation>Periode</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+16"/>
        <source>amplitude</source>
        <translation>Amplitude</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>phase</source>
        <translation>Phase</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>lag</source>
        <translation>Verzug</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>change per part</source>
        <translation>Änderung je Werkstück</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>scale</source>
        <translation>Maßstab</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>offset</source>
        <translation>Versatz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>angle</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>form</source>
        <translation>Form</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms</source>
        <translation>rms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>range</source>
        <translation>Spannweite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at</source>
        <translation>bei</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>harmonic</source>
        <translation>Harmonische</translation>
    </message>
</context>
</TS>
