<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pl_PL" sourcelanguage="en">
<context>
    <name>StudyInfo</name>
    <message>
        <location filename="../widgets/document/studyinfo.cpp" line="+16"/>
        <source>Setup correction</source>
        <translation>Korekcja danych ustawczych</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Posture matching</source>
        <translation>Dopasowanie położenia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kinematics &amp; SPC</source>
        <translation>Kinematyka i SPC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thermal</source>
        <translation>Termika</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diagnosis</source>
        <translation>Diagnoza</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Computes corrections of the work offsets and tool offsets from CMM reports through the relation graph of machine points, work coordinate systems, tools, features and dimensions. It maximises the smallest error budget over all dimensions with the certified exact optimum (LP, then MILP on the 0.001 mm grid) and compares CRIPSO, PSO, GA and COA against it in convergence charts. Corrections export as the controller takes them.</source>
        <translation>Oblicza korekcje przesunięć punktu zerowego i korekcje narzędzi na podstawie raportów WMP, korzystając z grafu relacji między punktami maszyny, układami współrzędnych przedmiotu, narzędziami, elementami geometrycznymi i wymiarami. Maksymalizuje najmniejszy zapas tolerancji spośród wszystkich wymiarów, wyznaczając potwierdzone optimum dokładne (LP, następnie MILP na siatce 0,001 mm), i porównuje z nim CRIPSO, PSO, GA oraz COA na wykresach zbieżności. Korekcje są eksportowane w postaci, jaką przyjmuje sterowanie.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Finds the actual posture of the workpiece from contact-probed points (nominal point, normal and measured point): rough matching from three reference points, fine matching by self-adaptive differential evolution, the closed-form least-squares optimum and a minimax tolerance-zone fit, then the adjustments of a 5-axis machine.</source>
        <translation>Wyznacza rzeczywiste położenie przedmiotu z punktów zmierzonych sondą stykową (punkt nominalny, normalna i punkt zmierzony): dopasowanie zgrubne z trzech punktów odniesienia, dopasowanie dokładne samoadaptacyjną ewolucją różnicową, optimum najmniejszych kwadratów w postaci zamkniętej oraz dopasowanie minimaksowe do strefy tolerancji, a następnie nastawy maszyny 5-osiowej.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Identifies the actuator origin offsets and orientation errors (squareness) of a Cartesian machine from a circular test or a measured path, computes compensated references for a nominal path, and charts measured features with X-bar/R control limits, Cp and Cpk.</source>
        <translation>Identyfikuje przesunięcia początków i błędy orientacji (prostopadłość) napędów maszyny kartezjańskiej na podstawie testu kołowego lub zmierzonej ścieżki, oblicza skompensowane wartości zadane dla ścieżki nominalnej i przedstawia zmierzone cechy na kartach kontrolnych X-średnie/R wraz z Cp i Cpk.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Models the thermal displacement of the spindle from temperature sensors with the grey model GMC(1,N), the grey neural network GNNMCI(1,N) trained by PSO and an MLP, fitted on the first part of a log and tested on the rest; shows sensor trends and hysteresis.</source>
        <translation>Modeluje przemieszczenie termiczne wrzeciona na podstawie czujników temperatury za pomocą szarego modelu GMC(1,N), szarej sieci neuronowej GNNMCI(1,N) uczonej metodą PSO oraz sieci MLP, dopasowanych do pierwszej części zapisu i sprawdzonych na pozostałej; pokazuje przebiegi czujników i histerezę.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Closes the loop: fits each declared model, looks at the residual it leaves, traces it to an effect the model lacks (thermal lag, an undeclared input, drift, backlash, scale, cyclic error, tool wear, surface offset and more), adds the effect only on strong out-of-sample evidence and reports the error before and after.</source>
        <translation>Zamyka pętlę: dopasowuje każdy zadeklarowany model, analizuje pozostawioną przez niego resztę, wiąże ją z efektem, którego modelowi brakuje (opóźnienie termiczne, niezadeklarowane wejście, dryft, luz zwrotny, skala, błąd cykliczny, zużycie narzędzia, przesunięcie powierzchni i inne), dodaje efekt tylko przy silnym potwierdzeniu poza próbą uczącą i podaje błąd przed i po.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Thermal log</source>
        <translation>Rejestr termiczny</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Probe points</source>
        <translation>Punkty sondowania</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Circular test</source>
        <translation>Test kołowy</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CMM report</source>
        <translation>Raport WMP</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setup model</source>
        <translation>Model ustawczy</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+21"/>
        <source>Metrofit — a workbench for machining error compensation.</source>
        <translation>Metrofit — warsztat do kompensacji błędów obróbki.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open the bundled demo project, save one PNG per main view into &lt;dir&gt; and exit (needs an X server; Xvfb will do).</source>
        <translation>Otwiera dołączony projekt demonstracyjny, zapisuje po jednym pliku PNG dla każdego widoku głównego w &lt;dir&gt; i kończy działanie (wymaga serwera X; wystarczy Xvfb).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>dir</source>
        <translation>katalog</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>project</source>
        <translation>projekt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A project file (.metrofit) to open.</source>
        <translation>Plik projektu (.metrofit) do otwarcia.</translation>
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
        <translation>Identyfikator</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>Rodzaj</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Path</source>
        <translation>Ścieżka</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Licence</source>
        <translation>Licencja</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>File not found: %1</source>
        <translation>Nie znaleziono pliku: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::FileChangedBar</name>
    <message>
        <location filename="../app/gui/filechangedbar.cpp" line="+20"/>
        <source>&amp;Reload</source>
        <translation>&amp;Wczytaj ponownie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Ignore</source>
        <translation>&amp;Ignoruj</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The project file %1 was changed by another program.</source>
        <translation>Plik projektu %1 został zmieniony przez inny program.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The project file %1 was removed or renamed by another program.</source>
        <translation>Plik projektu %1 został usunięty lub przemianowany przez inny program.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reloading discards your unsaved changes.</source>
        <translation>Ponowne wczytanie odrzuci niezapisane zmiany.</translation>
    </message>
</context>
<context>
    <name>metrofit::MainWindow</name>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="+42"/>
        <source>Metrofit projects (*.metrofit)</source>
        <translation>Projekty Metrofit (*.metrofit)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Cannot export the report</source>
        <translation>Nie można wyeksportować raportu</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Ready</source>
        <translation>Gotowe</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&amp;Overview</source>
        <translation>&amp;Przegląd</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;File</source>
        <translation>&amp;Plik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New</source>
        <translation>&amp;Nowy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open…</source>
        <translation>&amp;Otwórz…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open &amp;demo project</source>
        <translation>Otwórz projekt &amp;demonstracyjny</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Recent files</source>
        <translation>Ostatnio &amp;używane</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+100"/>
        <source>&amp;Save</source>
        <translation>&amp;Zapisz</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Save &amp;As…</source>
        <translation>Zapisz &amp;jako…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export report PDF…</source>
        <translation>&amp;Eksportuj raport PDF…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Quit</source>
        <translation>Za&amp;kończ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Edit</source>
        <translation>&amp;Edycja</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+6"/>
        <source>&amp;Undo</source>
        <translation>&amp;Cofnij</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+7"/>
        <source>&amp;Redo</source>
        <translation>&amp;Ponów</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>&amp;Undo %1</source>
        <translation>&amp;Cofnij: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Redo %1</source>
        <translation>&amp;Ponów: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Preferences…</source>
        <translation>&amp;Preferencje…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>&amp;Widok</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Project &amp;navigator</source>
        <translation>&amp;Nawigator projektu</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Help</source>
        <translation>Pomo&amp;c</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About Metrofit</source>
        <translation>&amp;O programie Metrofit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About &amp;Qt</source>
        <translation>O &amp;Qt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Project overview</source>
        <translation>Przegląd projektu</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1[*] — Metrofit</source>
        <translation>%1[*] — Metrofit</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>No recent files</source>
        <translation>Brak ostatnio używanych plików</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Clear list</source>
        <translation>&amp;Wyczyść listę</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot open the project</source>
        <translation>Nie można otworzyć projektu</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Opened %1</source>
        <translation>Otwarto %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Unsaved changes</source>
        <translation>Niezapisane zmiany</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The project &quot;%1&quot; has unsaved changes. Do you want to save them?</source>
        <translation>Projekt „%1” ma niezapisane zmiany. Czy chcesz je zapisać?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Discard</source>
        <translation>&amp;Odrzuć</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>New project</source>
        <translation>Nowy projekt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Open project</source>
        <translation>Otwórz projekt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot open the demo project</source>
        <translation>Nie można otworzyć projektu demonstracyjnego</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Demo project copied to %1</source>
        <translation>Projekt demonstracyjny skopiowano do %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+20"/>
        <source>Cannot save the project</source>
        <translation>Nie można zapisać projektu</translation>
    </message>
    <message>
        <location line="-16"/>
        <location line="+21"/>
        <source>Saved %1</source>
        <translation>Zapisano %1</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Save project as</source>
        <translation>Zapisz projekt jako</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Export report</source>
        <translation>Eksport raportu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF documents (*.pdf)</source>
        <translation>Dokumenty PDF (*.pdf)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Writing the report…</source>
        <translation>Zapisywanie raportu…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The new language is applied at the next start.</source>
        <translation>Nowy język zostanie zastosowany przy następnym uruchomieniu.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>About Metrofit</source>
        <translation>O programie Metrofit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;Metrofit %1&lt;/h3&gt;&lt;p&gt;A workbench for machining error compensation: setup-data correction, posture matching, kinematic compensation with SPC, thermal error models, and the closed-loop diagnosis of what a model lacks.&lt;/p&gt;&lt;p&gt;Licensed under the GNU General Public License, version 3 or later (GPL-3.0-or-later).&lt;/p&gt;&lt;p&gt;Built with Qt %2 (Qt Widgets, Qt Charts), VTK, Eigen %3 and GLPK.&lt;/p&gt;&lt;p&gt;The real thermal log of the demo project comes from the CAIVIAC data set and is used under the MIT licence.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Metrofit %1&lt;/h3&gt;&lt;p&gt;Warsztat do kompensacji błędów obróbki: korekcja danych ustawczych, dopasowanie położenia, kompensacja kinematyczna z SPC, modele błędów termicznych oraz diagnoza w pętli zamkniętej, która wykrywa, czego brakuje modelowi.&lt;/p&gt;&lt;p&gt;Licencja: GNU General Public License, wersja 3 lub późniejsza (GPL-3.0-or-later).&lt;/p&gt;&lt;p&gt;Zbudowano z użyciem Qt %2 (Qt Widgets, Qt Charts), VTK, Eigen %3 i GLPK.&lt;/p&gt;&lt;p&gt;Rzeczywisty rejestr termiczny w projekcie demonstracyjnym pochodzi ze zbioru danych CAIVIAC i jest używany na licencji MIT.&lt;/p&gt;</translation>
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
        <translation>Powierzchnia</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deviation before (mm)</source>
        <translation>Odchyłka przed (mm)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&amp;Probe points:</source>
        <translation>&amp;Punkty sondowania:</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>This project has no probe points. Add a dataset of kind &quot;probe_points&quot; to the project file (id, surface, nominal point, normal, measured point).</source>
        <translation>Ten projekt nie zawiera punktów sondowania. Dodaj do pliku projektu zbiór danych rodzaju „probe_points” (identyfikator, powierzchnia, punkt nominalny, normalna, punkt zmierzony).</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 points on %2 surfaces, %3. Before matching: RMS deviation %4 mm, largest %5 mm.</source>
        <translation>Punkty: %1, powierzchnie: %2, %3. Przed dopasowaniem: odchyłka średniokwadratowa %4 mm, największa %5 mm.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>with normals</source>
        <translation>z normalnymi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>positions only</source>
        <translation>tylko położenia</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Licence: %1.</source>
        <translation>Licencja: %1.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot show these probe points:
%1</source>
        <translation>Nie można wyświetlić tych punktów sondowania:
%1</translation>
    </message>
</context>
<context>
    <name>metrofit::NotesEdit</name>
    <message>
        <location filename="../app/gui/notesedit.cpp" line="+10"/>
        <source>Notes on the %1 study (saved with the project)</source>
        <translation>Notatki do studium „%1” (zapisywane z projektem)</translation>
    </message>
</context>
<context>
    <name>metrofit::OverviewPage</name>
    <message>
        <location filename="../app/gui/overviewpage.cpp" line="+23"/>
        <source>Project overview</source>
        <translation>Przegląd projektu</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Project name</source>
        <translation>Nazwa projektu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What is measured, on which machine, and why</source>
        <translation>Co jest mierzone, na jakiej maszynie i dlaczego</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Name:</source>
        <translation>&amp;Nazwa:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Description:</source>
        <translation>&amp;Opis:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File:</source>
        <translation>Plik:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Datasets</source>
        <translation>Zbiory danych</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>not saved yet</source>
        <translation>jeszcze nie zapisano</translation>
    </message>
</context>
<context>
    <name>metrofit::PreferencesDialog</name>
    <message>
        <location filename="../app/gui/preferencesdialog.cpp" line="+16"/>
        <source>Preferences</source>
        <translation>Preferencje</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System</source>
        <translation>Systemowy</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The language is applied at the next start of Metrofit.</source>
        <translation>Język zostanie zastosowany przy następnym uruchomieniu programu Metrofit.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Language:</source>
        <translation>&amp;Język:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
</context>
<context>
    <name>metrofit::ProjectDocument</name>
    <message>
        <location filename="../widgets/document/projectdocument.cpp" line="+30"/>
        <source>Rename project</source>
        <translation>Zmiana nazwy projektu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edit project description</source>
        <translation>Edycja opisu projektu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edit notes of %1</source>
        <translation>Edycja notatek: %1</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Untitled</source>
        <translation>Bez nazwy</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>the project has not been saved yet; choose a file name with Save As</source>
        <translation>projekt nie został jeszcze zapisany; wybierz nazwę pliku poleceniem „Zapisz jako”</translation>
    </message>
</context>
<context>
    <name>metrofit::ProjectNavigator</name>
    <message>
        <location filename="../app/gui/projectnavigator.cpp" line="+50"/>
        <location line="+11"/>
        <source>%1: project overview (Ctrl+1)</source>
        <translation>%1: przegląd projektu (Ctrl+1)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (Ctrl+%2)</source>
        <translation>%1 (Ctrl+%2)</translation>
    </message>
</context>
<context>
    <name>metrofit::ReportExporter</name>
    <message>
        <location filename="../app/gui/reportexporter.cpp" line="+51"/>
        <source>Cannot prepare the report: %1</source>
        <translation>Nie można przygotować raportu: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Cannot run %1: %2</source>
        <translation>Nie można uruchomić %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Writing the report…</source>
        <translation>Zapisywanie raportu…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export report</source>
        <translation>Eksport raportu</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The report export was cancelled.</source>
        <translation>Eksport raportu został anulowany.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>metrofit-cli stopped unexpectedly while writing %1.</source>
        <translation>metrofit-cli nieoczekiwanie zakończył działanie podczas zapisywania %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Report written to %1.</source>
        <translation>Raport zapisano w %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>metrofit-cli failed with exit code %1.</source>
        <translation>metrofit-cli zakończył się błędem (kod wyjścia %1).</translation>
    </message>
</context>
<context>
    <name>metrofit::StudyPage</name>
    <message>
        <location filename="../app/gui/studypage.cpp" line="+31"/>
        <source>The views of this study are not part of this version of the workbench yet. Nothing has been computed: the datasets it will work on are listed below.</source>
        <translation>Widoki tego studium nie są jeszcze częścią tej wersji warsztatu. Nic nie zostało obliczone: poniżej wymieniono zbiory danych, na których będzie ono pracować.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>What this study does</source>
        <translation>Co robi to studium</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Datasets</source>
        <translation>Zbiory danych</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Notes</source>
        <translation>Notatki</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>This project has no datasets for this study yet (it uses: %1).</source>
        <translation>Ten projekt nie ma jeszcze zbiorów danych dla tego studium (wykorzystuje ono: %1).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data this study uses: %1.</source>
        <translation>Dane wykorzystywane przez to studium: %1.</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalPage</name>
    <message>
        <location filename="../app/gui/thermalpage.cpp" line="+48"/>
        <source>&amp;Thermal log:</source>
        <translation>&amp;Rejestr termiczny:</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>This project has no thermal log. Add a dataset of kind &quot;thermal_log&quot; to the project file (a time column, sensor columns and the displacement).</source>
        <translation>Ten projekt nie zawiera rejestru termicznego. Dodaj do pliku projektu zbiór danych rodzaju „thermal_log” (kolumna czasu, kolumny czujników i przemieszczenie).</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 rows, %2 channels, %3 h.</source>
        <translation>Wiersze: %1, kanały: %2, czas: %3 h.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Licence: %1.</source>
        <translation>Licencja: %1.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot show this thermal log:
%1</source>
        <translation>Nie można wyświetlić tego rejestru termicznego:
%1</translation>
    </message>
</context>
</TS>
