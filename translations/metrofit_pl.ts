<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pl_PL" sourcelanguage="en">
<context>
    <name>StudyInfo</name>
    <message>
        <location filename="../widgets/document/studyinfo.cpp" line="+18"/>
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
        <location line="+29"/>
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
    <message>
        <location line="+2"/>
        <source>SPC feature series</source>
        <translation>Seria cech SPC</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>DMIS output</source>
        <translation>Wynik DMIS</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hole table</source>
        <translation>Tabela otworów</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Q-DAS DFQ file</source>
        <translation>Plik Q-DAS DFQ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zeiss Calypso table</source>
        <translation>Tabela Zeiss Calypso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAD part (STL)</source>
        <translation>Część CAD (STL)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>QIF results</source>
        <translation>Wyniki QIF</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MTConnect log</source>
        <translation>Dziennik MTConnect</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+23"/>
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
        <location line="+3"/>
        <source>User interface language for this run: en, de or pl (overrides the Preferences; the screenshots are in English without it).</source>
        <translation>Język interfejsu użytkownika dla tego uruchomienia: en, de lub pl (ma pierwszeństwo przed preferencjami; bez tej opcji zrzuty ekranu są w języku angielskim).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>language</source>
        <translation>język</translation>
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
    <name>metrofit::Autosave</name>
    <message>
        <location filename="../app/gui/autosave.cpp" line="+186"/>
        <source>cannot create the autosave folder %1</source>
        <translation>nie można utworzyć folderu automatycznego zapisu %1</translation>
    </message>
    <message>
        <location line="+69"/>
        <location line="+60"/>
        <source>The autosaved copy cannot be read: %1</source>
        <translation>Nie można odczytać automatycznie zapisanej kopii: %1</translation>
    </message>
    <message>
        <location line="-44"/>
        <location line="+54"/>
        <location line="+52"/>
        <source>Recover autosaved changes</source>
        <translation>Przywracanie automatycznie zapisanych zmian</translation>
    </message>
    <message>
        <location line="-23"/>
        <source>An autosaved edit cannot be recovered: %1</source>
        <translation>Nie można przywrócić automatycznie zapisanej zmiany: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Metrofit was not closed properly. An autosaved copy of the unsaved project “%1” from %2 was found.

Do you want to recover it?</source>
        <translation>Program Metrofit nie został poprawnie zamknięty. Znaleziono automatycznie zapisaną kopię niezapisanego projektu „%1” z %2.

Czy chcesz ją przywrócić?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The project %1 has an autosaved copy from %2 that is newer than the file (saved %3). Metrofit was probably not closed properly.

Do you want to recover the autosaved changes? They are opened as unsaved changes; the project file is only overwritten when you save.</source>
        <translation>Projekt %1 ma automatycznie zapisaną kopię z %2, nowszą niż plik (zapisany %3). Program Metrofit prawdopodobnie nie został poprawnie zamknięty.

Czy chcesz przywrócić automatycznie zapisane zmiany? Zostaną otwarte jako niezapisane zmiany; plik projektu zostanie nadpisany dopiero przy zapisie.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The autosaved copy includes unsaved edits of the setup model (relation graph); they are recovered as unsaved edits too.</source>
        <translation>Automatycznie zapisana kopia zawiera niezapisane zmiany modelu ustawczego (graf relacji); one również zostaną przywrócone jako niezapisane zmiany.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Recover</source>
        <translation>&amp;Przywróć</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Discard</source>
        <translation>O&amp;drzuć</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Keep for later</source>
        <translation>&amp;Zachowaj na później</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Open original</source>
        <translation>&amp;Otwórz oryginał</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open the autosaved content as unsaved changes</source>
        <translation>Otwórz automatycznie zapisaną zawartość jako niezapisane zmiany</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete the autosaved copy</source>
        <translation>Usuń automatycznie zapisaną kopię</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Leave the autosaved copy where it is and continue without it</source>
        <translation>Pozostaw automatycznie zapisaną kopię na miejscu i kontynuuj bez niej</translation>
    </message>
</context>
<context>
    <name>metrofit::BackgroundRunBase</name>
    <message>
        <location filename="../widgets/common/backgroundrun.cpp" line="+112"/>
        <source>unknown error</source>
        <translation>nieznany błąd</translation>
    </message>
</context>
<context>
    <name>metrofit::BallbarText</name>
    <message>
        <location filename="../widgets/kinematics/ballbartext.cpp" line="+30"/>
        <source>Backlash %1</source>
        <translation>Luz zwrotny %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reversal spikes %1</source>
        <translation>Piki przy nawrocie %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lateral play %1</source>
        <translation>Luz poprzeczny %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Straightness %1</source>
        <translation>Prostoliniowość %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cyclic error %1</source>
        <translation>Błąd cykliczny %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Servo mismatch</source>
        <translation>Niedopasowanie serwonapędów</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scale mismatch</source>
        <translation>Niedopasowanie skali X/Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Squareness</source>
        <translation>Prostopadłość</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unexplained (RMS)</source>
        <translation>Niewyjaśnione (RMS)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Lost motion of the %1 axis at its reversals: the axis lags half of it behind its direction of motion</source>
        <translation>Martwy ruch osi %1 w punktach nawrotu: oś pozostaje o jego połowę w tyle za kierunkiem ruchu</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Peak of a short lag of the %1 axis after each reversal, decaying over about 2° of the path; positive: outwards</source>
        <translation>Szczyt krótkiego opóźnienia osi %1 po każdym nawrocie, zanikającego na około 2° ścieżki; dodatni: na zewnątrz</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Sideways step of the %1 carriage when its axis reverses</source>
        <translation>Boczny uskok sań %1 przy nawrocie ich osi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bow of the %1 axis across the test diameter (its middle relative to its ends)</source>
        <translation>Ugięcie osi %1 na średnicy testu (jej środek względem jej końców)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Amplitude of the periodic error of the %1 axis with the screw pitch</source>
        <translation>Amplituda błędu okresowego osi %1 o okresie skoku śruby</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Difference of the X and Y following errors at the test&apos;s feed; positive: X lags more</source>
        <translation>Różnica uchybów nadążania X i Y przy posuwie testu; dodatnia: X opóźnia się bardziej</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(Scale of X − scale of Y) × radius; positive: X travels further than Y</source>
        <translation>(skala X − skala Y) × promień; dodatnie: X przesuwa się dalej niż Y</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Squareness error (b − a) × radius: the shear over the test radius</source>
        <translation>Błąd prostopadłości (b − a) × promień: ścinanie na promieniu testu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RMS of what the causes leave: noise and errors not in the list</source>
        <translation>RMS tego, co pozostawiają przyczyny: szum i błędy spoza listy</translation>
    </message>
</context>
<context>
    <name>metrofit::ChartExport</name>
    <message>
        <location filename="../widgets/common/chartexport.cpp" line="+137"/>
        <source>Export chart as SVG</source>
        <translation>Eksport wykresu jako SVG</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Export chart as PNG</source>
        <translation>Eksport wykresu jako PNG</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SVG drawings (*.svg)</source>
        <translation>Rysunki SVG (*.svg)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PNG images (*.png)</source>
        <translation>Obrazy PNG (*.png)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Chart exported to %1</source>
        <translation>Wyeksportowano wykres do %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cannot export the chart: %1</source>
        <translation>Nie można wyeksportować wykresu: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export as &amp;PNG…</source>
        <translation>Eksportuj jako &amp;PNG…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save this chart as a PNG image (the size it has on screen)</source>
        <translation>Zapisz ten wykres jako obraz PNG (w rozmiarze, jaki ma na ekranie)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export as &amp;SVG…</source>
        <translation>Eksportuj jako &amp;SVG…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save this chart as an SVG drawing (lines and text stay sharp)</source>
        <translation>Zapisz ten wykres jako rysunek SVG (linie i tekst pozostają ostre)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Copy image</source>
        <translation>&amp;Kopiuj obraz</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Chart copied to the clipboard</source>
        <translation>Skopiowano wykres do schowka</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>the chart has no picture to export</source>
        <translation>wykres nie zawiera obrazu do wyeksportowania</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+21"/>
        <location line="+11"/>
        <source>cannot write %1</source>
        <translation>nie można zapisać %1</translation>
    </message>
    <message>
        <location line="-24"/>
        <source>a 3D view can only be exported as PNG</source>
        <translation>widok 3D można wyeksportować tylko jako PNG</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Exported from Metrofit</source>
        <translation>Wyeksportowano z programu Metrofit</translation>
    </message>
</context>
<context>
    <name>metrofit::ChartNavigation</name>
    <message>
        <location filename="../widgets/common/chartnavigation.cpp" line="+139"/>
        <location filename="../widgets/common/plotnavigation.cpp" line="+46"/>
        <source>&amp;Reset zoom (double click, Home)</source>
        <translation>&amp;Resetuj powiększenie (dwuklik, Home)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../widgets/common/plotnavigation.cpp" line="+2"/>
        <source>Show the whole chart again</source>
        <translation>Pokaż znów cały wykres</translation>
    </message>
</context>
<context>
    <name>metrofit::CircularPathView</name>
    <message>
        <location filename="../widgets/kinematics/kinematicsviews.cpp" line="+60"/>
        <source>point %1 (%2)
x: %3 mm, y: %4 mm
radial deviation: %5 µm</source>
        <translation>punkt %1 (%2)
x: %3 mm; y: %4 mm
odchyłka promieniowa: %5 µm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CCW</source>
        <translation>CCW</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CW</source>
        <translation>CW</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The XY path in mm: the nominal circle true to scale; the measured path, the compensated references and the expected result as deviations from the nominal point, magnified by the factor shown.</source>
        <translation>Tor XY w mm: okrąg nominalny w skali; zmierzony tor, skompensowane wartości zadane i oczekiwany wynik jako odchyłki od punktu nominalnego, powiększone o podany współczynnik.</translation>
    </message>
</context>
<context>
    <name>metrofit::ControlChartView</name>
    <message>
        <location line="+89"/>
        <source>subgroup %1
mean: %2%3</source>
        <translation>podgrupa %1
średnia: %2%3</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>subgroup %1
range: %2%3</source>
        <translation>podgrupa %1
rozstęp: %2%3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Subgroup means with the centre line and the control limits UCL/LCL = mean ± A2 · R̄ (kinematic-compensation paper, Eq. 18–19); red points are out of control, ringed ones break a Nelson rule (the read-out names it).</source>
        <translation>Średnie podgrup z linią centralną i granicami kontrolnymi GGK/DGK = średnia ± A2 · R̄ (artykuł o kompensacji kinematycznej, wz. 18–19); czerwone punkty są poza granicami, obwiedzione łamią regułę Nelsona (odczyt ją nazywa).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Subgroup ranges with the centre line R̄ and the limits D4 · R̄ and D3 · R̄.</source>
        <translation>Rozstępy podgrup z linią centralną R̄ i granicami D4 · R̄ oraz D3 · R̄.</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetActions</name>
    <message>
        <location filename="../app/gui/datasetactions.cpp" line="+55"/>
        <source>%1 — data</source>
        <translation>%1 — dane</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>&amp;Show data</source>
        <translation>&amp;Pokaż dane</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Rename dataset…</source>
        <translation>&amp;Zmień nazwę zbioru danych…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Re-&amp;link to a moved file…</source>
        <translation>Połącz z &amp;przeniesionym plikiem…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Re&amp;move dataset</source>
        <translation>&amp;Usuń zbiór danych</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Remove the dataset “%1” from the project? The file itself stays where it is.</source>
        <translation>Usunąć zbiór danych „%1” z projektu? Sam plik pozostaje na miejscu.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>These study settings name it and are removed with it: %1</source>
        <translation>Te ustawienia badań go wskazują i zostaną usunięte razem z nim: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Remove dataset</source>
        <translation>Usuń zbiór danych</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot remove the dataset</source>
        <translation>Nie można usunąć zbioru danych</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Rename dataset</source>
        <translation>Zmień nazwę zbioru danych</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New id of “%1” (study settings that name it follow):</source>
        <translation>Nowy identyfikator „%1” (ustawienia badań, które go wskazują, zostaną zaktualizowane):</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot rename the dataset</source>
        <translation>Nie można zmienić nazwy zbioru danych</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Re-link the %1 files of the series “%2”</source>
        <translation>Połącz ponownie %1 plików serii „%2”</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Re-link dataset “%1”</source>
        <translation>Połącz ponownie zbiór danych „%1”</translation>
    </message>
    <message>
        <location line="-3"/>
        <location line="+4"/>
        <source>All files (*)</source>
        <translation>Wszystkie pliki (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot re-link the dataset</source>
        <translation>Nie można ponownie połączyć zbioru danych</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetTable</name>
    <message>
        <location filename="../app/gui/datasettable.cpp" line="+23"/>
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
        <location line="+48"/>
        <source>File not found: %1</source>
        <translation>Nie znaleziono pliku: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetTableModel</name>
    <message>
        <location filename="../widgets/data/datasettablemodel.cpp" line="+139"/>
        <source>out of tolerance</source>
        <translation>poza tolerancją</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no tolerance</source>
        <translation>brak tolerancji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>in tolerance</source>
        <translation>w tolerancji</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Line %1 of the file</source>
        <translation>Wiersz %1 pliku</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Deviation %1 %2 is outside the tolerance %3 … %4</source>
        <translation>Odchyłka %1 %2 leży poza tolerancją %3 … %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The report marks this value out of tolerance</source>
        <translation>Raport oznacza tę wartość jako poza tolerancją</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Part</source>
        <translation>Część</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Feature</source>
        <translation>Element</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Characteristic</source>
        <translation>Charakterystyka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unit</source>
        <translation>Jednostka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nominal</source>
        <translation>Nominalna</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Actual</source>
        <translation>Rzeczywista</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Deviation</source>
        <translation>Odchyłka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lower tol.</source>
        <translation>Tol. dolna</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Upper tol.</source>
        <translation>Tol. górna</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The file&apos;s column “%1”, read as %2</source>
        <translation>Kolumna pliku „%1”, czytana jako %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The file&apos;s column “%1”</source>
        <translation>Kolumna pliku „%1”</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Actual − nominal (plain sign; OGP prints locations with the sign of the nominal)</source>
        <translation>Rzeczywista − nominalna (zwykły znak; OGP drukuje położenia ze znakiem wartości nominalnej)</translation>
    </message>
</context>
<context>
    <name>metrofit::DatasetView</name>
    <message>
        <location filename="../widgets/data/datasetview.cpp" line="+108"/>
        <source>Filter rows (text in any column)</source>
        <translation>Filtruj wiersze (tekst w dowolnej kolumnie)</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>&amp;Filter:</source>
        <translation>&amp;Filtr:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Plot:</source>
        <translation>&amp;Wykres:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;against</source>
        <translation>&amp;względem</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Reading %1…</source>
        <translation>Wczytywanie %1…</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Cannot show %1: %2</source>
        <translation>Nie można pokazać %1: %2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>(none)</source>
        <translation>(brak)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>row number</source>
        <translation>numer wiersza</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Deviation</source>
        <translation>Odchyłka</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1, %2 rows</source>
        <translation>%1, wiersze: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n out of tolerance</source>
        <translation>
            <numerusform>%n poza tolerancją</numerusform>
            <numerusform>%n poza tolerancją</numerusform>
            <numerusform>%n poza tolerancją</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 shown</source>
        <translation>pokazano: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>row</source>
        <translation>wiersz</translation>
    </message>
</context>
<context>
    <name>metrofit::DiagnosisPage</name>
    <message>
        <location filename="../app/gui/diagnosispage.cpp" line="+75"/>
        <source>Thermal</source>
        <translation>Termika</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kinematic</source>
        <translation>Kinematyka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setup</source>
        <translation>Ustawienie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Matching</source>
        <translation>Dopasowanie</translation>
    </message>
    <message>
        <location line="+653"/>
        <source>Apply diagnosed effects (%1)</source>
        <translation>Zastosuj zdiagnozowane efekty (%1)</translation>
    </message>
    <message>
        <location line="-549"/>
        <source>&amp;Run</source>
        <translation>&amp;Uruchom</translation>
    </message>
    <message>
        <location line="-86"/>
        <source>mm/part</source>
        <translation>mm/przedmiot</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Apply to model</source>
        <translation>Zastosuj do &amp;modelu</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>The study whose declared model is diagnosed</source>
        <translation>Studium, którego zadeklarowany model jest diagnozowany</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fit the declared model, try the candidate effects it lacks, accept those the evidence supports (Ctrl+R)</source>
        <translation>Dopasuj zadeklarowany model, wypróbuj brakujące w nim efekty kandydujące, przyjmij te, które potwierdzają dowody (Ctrl+R)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stop the loop; the rounds done so far are shown (Esc)</source>
        <translation>Zatrzymaj pętlę; pokazane zostaną dotychczasowe rundy (Esc)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+341"/>
        <source>Add the accepted effects to the study&apos;s model in the project (undoable, Ctrl+Shift+A)</source>
        <translation>Dodaj przyjęte efekty do modelu studium w projekcie (można cofnąć, Ctrl+Shift+A)</translation>
    </message>
    <message>
        <location line="-327"/>
        <source>The declared model as fitted before any effect was added</source>
        <translation>Zadeklarowany model dopasowany przed dodaniem jakiegokolwiek efektu</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The effect whose residual plot is shown</source>
        <translation>Efekt, którego wykres residuów jest pokazany</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Residual &amp;plot of:</source>
        <translation>Wykres &amp;residuów dla:</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Round</source>
        <translation>Runda</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Effect</source>
        <translation>Efekt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parameters (± standard error)</source>
        <translation>Parametry (± błąd standardowy)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rmse before → after</source>
        <translation>rmse przed → po</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>held-out rmse</source>
        <translation>rmse danych testowych</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Evidence</source>
        <translation>Dowody</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accepted</source>
        <translation>Przyjęty</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Every candidate effect tried, in the order tried (Ctrl+C copies the selected rows)</source>
        <translation>Wszystkie wypróbowane efekty kandydujące w kolejności prób (Ctrl+C kopiuje zaznaczone wiersze)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopiuj</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Effects</source>
        <translation>&amp;Efekty</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+191"/>
        <location line="+114"/>
        <source>Residual chec&amp;k</source>
        <translation>Sprawdzenie re&amp;siduów</translation>
    </message>
    <message>
        <location line="-303"/>
        <source>The candidate effects tried, their residual plots and the error before / after</source>
        <translation>Wypróbowane efekty kandydujące, ich wykresy residuów i błąd przed / po</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>What the final residual still depends on: tests, structure, outliers and the residual against the variable of the strongest structure</source>
        <translation>Od czego końcowe residuum jeszcze zależy: testy, struktura, wartości odstające i residuum względem zmiennej najsilniejszej struktury</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Domain:</source>
        <translation>&amp;Dziedzina:</translation>
    </message>
    <message>
        <location line="+52"/>
        <location line="+156"/>
        <source>The diagnosis failed: %1</source>
        <translation>Diagnoza nie powiodła się: %1</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>Data: %1</source>
        <translation>Dane: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>; target %1; declared inputs %2; fitted on the first %3 % of the rows, held out on the rest.</source>
        <translation>; wielkość docelowa %1; zadeklarowane wejścia %2; dopasowano na pierwszych %3 % wierszy, reszta to dane testowe.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>; declared model: Cartesian actuator errors (origin, axis angles); feed %1 mm/min.</source>
        <translation>; zadeklarowany model: kartezjańskie błędy napędów (początek, kąty osi); posuw %1 mm/min.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>; setup model %1; declared model: constant setup-data errors.</source>
        <translation>; model ustawczy %1; zadeklarowany model: stałe błędy danych ustawczych.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>; declared model: rigid posture; tolerance ±%1 mm.</source>
        <translation>; zadeklarowany model: sztywne położenie; tolerancja ±%1 mm.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Applied to the model: %1.</source>
        <translation>Zastosowano do modelu: %1.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Not run yet: press Run (Ctrl+R).</source>
        <translation>Jeszcze nie uruchomiono: naciśnij Uruchom (Ctrl+R).</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Diagnosing …</source>
        <translation>Diagnozowanie …</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Diagnosing … step %1, current rmse %2</source>
        <translation>Diagnozowanie … krok %1, bieżący rmse %2</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1: a generic effect of the data row, the part or the dimension says nothing about the next part, so the study (%2) cannot include it; it is reported here and in the residual check, not applied</source>
        <translation>%1: efekt ogólny wiersza danych, części lub wymiaru nic nie mówi o następnej części, więc badanie (%2) nie może go uwzględnić; jest raportowany tutaj i w sprawdzeniu residuum, ale nie zastosowany</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Nothing to apply. %1.</source>
        <translation>Nie ma czego zastosować. %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Applies %1 only. %2.</source>
        <translation>Stosuje tylko %1. %2.</translation>
    </message>
    <message>
        <location line="+217"/>
        <source>The dataset the %1 diagnosis runs on (studies.diagnosis.%2.dataset)</source>
        <translation>Zbiór danych, na którym działa diagnoza (%1) (studies.diagnosis.%2.dataset)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Da&amp;ta:</source>
        <translation>Da&amp;ne:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Choose the %1 diagnosis data</source>
        <translation>Wybierz dane diagnozy (%1)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Train &amp;fraction:</source>
        <translation>&amp;Udział uczący:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The share of the rows (from the start) the model is fitted on; the rest is held out (studies.diagnosis.thermal.train_fraction)</source>
        <translation>Udział wierszy (od początku), do których dopasowywany jest model; reszta to dane testowe (studies.diagnosis.thermal.train_fraction)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change the diagnosis train fraction</source>
        <translation>Zmień udział uczący diagnozy</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The log&apos;s column the declared model predicts, whose residual is diagnosed (studies.diagnosis.thermal.target)</source>
        <translation>Kolumna dziennika przewidywana przez zadeklarowany model, której reszta jest diagnozowana (studies.diagnosis.thermal.target)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tar&amp;get:</source>
        <translation>&amp;Cel:</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Change the diagnosis target</source>
        <translation>Zmień cel diagnozy</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The declared model&apos;s inputs: the loop looks for what the residual of a model of these inputs still depends on (studies.diagnosis.thermal.inputs)</source>
        <translation>Wejścia zadeklarowanego modelu: pętla szuka, od czego jeszcze zależy reszta modelu tych wejść (studies.diagnosis.thermal.inputs)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Inputs:</source>
        <translation>&amp;Wejścia:</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&amp;Feed:</source>
        <translation>&amp;Posuw:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The feed of the circular test, for the servo lag&apos;s time constant (studies.diagnosis.kinematic.feed_mm_per_min)</source>
        <translation>Posuw testu kołowego, dla stałej czasowej uchybu nadążania (studies.diagnosis.kinematic.feed_mm_per_min)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change the diagnosis feed</source>
        <translation>Zmień posuw diagnozy</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The setup model whose setup data are diagnosed (studies.diagnosis.setup.model)</source>
        <translation>Model ustawień, którego dane ustawcze są diagnozowane (studies.diagnosis.setup.model)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Model:</source>
        <translation>&amp;Model:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Choose the diagnosis setup model</source>
        <translation>Wybierz model ustawień diagnozy</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Tolerance ±:</source>
        <translation>&amp;Tolerancja ±:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The symmetric tolerance an effect must matter against (studies.diagnosis.matching.tolerance_mm)</source>
        <translation>Symetryczna tolerancja, względem której efekt musi mieć znaczenie (studies.diagnosis.matching.tolerance_mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change the diagnosis tolerance</source>
        <translation>Zmień tolerancję diagnozy</translation>
    </message>
    <message numerus="yes">
        <location line="+126"/>
        <source>%n column(s)</source>
        <translation>
            <numerusform>%n kolumna</numerusform>
            <numerusform>%n kolumny</numerusform>
            <numerusform>%n kolumn</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Change the diagnosis inputs</source>
        <translation>Zmień wejścia diagnozy</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+33"/>
        <location line="+2"/>
        <source>Choose the thermal diagnosis data</source>
        <translation>Wybierz dane diagnozy termicznej</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>The stored result (computed %1) is out of date: the settings changed since. Not run with these settings yet: press Run (Ctrl+R).</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: ustawienia zmieniły się od tego czasu. Jeszcze nie uruchomiono z tymi ustawieniami: naciśnij Uruchom (Ctrl+R).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the data file changed since. Run (Ctrl+R) on the data as it is now.</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: plik danych zmienił się od tego czasu. Uruchom (Ctrl+R) na danych w obecnej postaci.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the data file cannot be read.</source>
        <translation>Nie można sprawdzić zapisanego wyniku (obliczonego %1): nie można odczytać pliku danych.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>From the saved project (computed %1 with these settings on this data): %2 Run (Ctrl+R) for the plots, the candidate table and the residual check.</source>
        <translation>Z zapisanego projektu (obliczono %1 z tymi ustawieniami dla tych danych): %2 Uruchom (Ctrl+R), aby zobaczyć wykresy, tabelę kandydatów i sprawdzenie residuów.</translation>
    </message>
    <message>
        <location line="-1034"/>
        <source>rmse %1 → %2 %3</source>
        <translation>rmse %1 → %2 %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, held-out rmse %1 → %2 %3</source>
        <translation>, rmse danych testowych %1 → %2 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, max |e| %1 → %2 %3</source>
        <translation>, maks. |e| %1 → %2 %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>. No undeclared effect found (%1 candidates tried).</source>
        <translation>. Nie znaleziono niezadeklarowanego efektu (wypróbowano kandydatów: %1).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>. Accepted: %1 (%2 candidates tried).</source>
        <translation>. Przyjęto: %1 (wypróbowano kandydatów: %2).</translation>
    </message>
    <message>
        <location line="+290"/>
        <source>Diagnosis, %1: the settings are invalid; nothing runs until they are corrected (above, Undo, or the project file under studies.diagnosis.%2):
%3</source>
        <translation>Diagnoza, %1: ustawienia są nieprawidłowe; nic nie zostanie uruchomione, dopóki nie zostaną poprawione (powyżej, Cofnij lub plik projektu w studies.diagnosis.%2):
%3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Diagnosis, %1: choose the data to diagnose above (Data).</source>
        <translation>Diagnoza, %1: wybierz powyżej dane do diagnozy (Dane).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Diagnosis, %1: the project has no data for it yet. Import it with File › Import data (Ctrl+I).</source>
        <translation>Diagnoza, %1: projekt nie ma jeszcze danych do niej. Zaimportuj je przez Plik › Importuj dane (Ctrl+I).</translation>
    </message>
    <message>
        <location line="+156"/>
        <source>Cancelled: the rounds done so far.</source>
        <translation>Anulowano: dotychczasowe rundy.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Residual check: %1.</source>
        <translation>Sprawdzenie residuów: %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Residual chec&amp;k: white</source>
        <translation>Sprawdzenie re&amp;siduów: białe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Residual chec&amp;k: structure left</source>
        <translation>Sprawdzenie re&amp;siduów: pozostała struktura</translation>
    </message>
    <message>
        <location line="+7"/>
        <source> (accepted)</source>
        <translation> (przyjęty)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Residual before and after %1</source>
        <translation>Residua przed i po %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>form: %1</source>
        <translation>postać: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A generic effect: %1 in %2, for structure no catalogue effect explains</source>
        <translation>Efekt ogólny: %1 względem %2, dla struktury, której nie wyjaśnia żaden efekt z katalogu</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>(Already applied.)</source>
        <translation>(Już zastosowano.)</translation>
    </message>
</context>
<context>
    <name>metrofit::ErrorBarsView</name>
    <message>
        <location filename="../widgets/diagnose/residualplot.cpp" line="+449"/>
        <source>rmse and largest |error| of the fitted data, rmse of the held-out rows (thermal): the declared model (grey) and the model with the accepted effects (blue)</source>
        <translation>rmse i największy |błąd| danych dopasowania, rmse wierszy testowych (termika): zadeklarowany model (szary) i model z przyjętymi efektami (niebieski)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Error before / after</source>
        <translation>Błąd przed / po</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Error before / after (%1)</source>
        <translation>Błąd przed / po (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared</source>
        <translation>zadeklarowany</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+ effects</source>
        <translation>+ efekty</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>rmse</source>
        <translation>rmse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max |e|</source>
        <translation>maks. |e|</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>held-out</source>
        <translation>dane testowe</translation>
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
    <name>metrofit::HistogramView</name>
    <message>
        <location filename="../widgets/kinematics/kinematicsviews.cpp" line="+43"/>
        <source>%1 to %2%3
count: %4</source>
        <translation>od %1 do %2%3
liczba: %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Distribution of the values with the specification limits LSL/USL, the nominal and the mean.</source>
        <translation>Rozkład wartości z granicami specyfikacji LSL/USL, wartością nominalną i średnią.</translation>
    </message>
</context>
<context>
    <name>metrofit::ImportDialog</name>
    <message>
        <location filename="../widgets/importer/importdialog.cpp" line="+69"/>
        <location line="+15"/>
        <source>comma ( , )</source>
        <translation>przecinek ( , )</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>semicolon ( ; )</source>
        <translation>średnik ( ; )</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tab</source>
        <translation>tabulator</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+11"/>
        <location line="+150"/>
        <source>detect</source>
        <translation>wykryj</translation>
    </message>
    <message>
        <location line="-154"/>
        <source>point ( . )</source>
        <translation>kropka ( . )</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>time in s, strictly increasing</source>
        <translation>czas w s, ściśle rosnący</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time in min</source>
        <translation>czas w min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time in h</source>
        <translation>czas w h</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacement in X in µm (a target)</source>
        <translation>przemieszczenie w X w µm (wielkość docelowa)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacement in Y in µm (a target)</source>
        <translation>przemieszczenie w Y w µm (wielkość docelowa)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacement in Z in µm (a target)</source>
        <translation>przemieszczenie w Z w µm (wielkość docelowa)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ambient temperature in °C</source>
        <translation>temperatura otoczenia w °C</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spindle speed in 1/min</source>
        <translation>prędkość obrotowa wrzeciona w 1/min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>point id</source>
        <translation>identyfikator punktu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>surface name</source>
        <translation>nazwa powierzchni</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>nominal point in mm</source>
        <translation>punkt nominalny w mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>nominal unit normal</source>
        <translation>nominalny wektor normalny</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>measured point in mm</source>
        <translation>punkt zmierzony w mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>commanded coordinate in mm</source>
        <translation>współrzędna zadana w mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>measured coordinate in mm</source>
        <translation>współrzędna zmierzona w mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>angle of a radial-only circular test in deg</source>
        <translation>kąt testu okrągłości tylko z odchyłkami promieniowymi w stopniach</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>radial deviation in µm (radial-only circular test)</source>
        <translation>odchyłka promieniowa w µm (test okrągłości tylko promieniowy)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>radial deviation in mm (radial-only circular test)</source>
        <translation>odchyłka promieniowa w mm (test okrągłości tylko promieniowy)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>direction of travel: ccw or cw</source>
        <translation>kierunek ruchu: ccw (przeciwnie do wskazówek zegara) lub cw (zgodnie)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>run number</source>
        <translation>numer przebiegu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nominal radius in mm</source>
        <translation>promień nominalny w mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part number</source>
        <translation>numer części</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dimension id of the setup model</source>
        <translation>identyfikator wymiaru modelu ustawczego</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nominal value in mm</source>
        <translation>wartość nominalna w mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured value in mm</source>
        <translation>wartość zmierzona w mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lower tolerance in mm</source>
        <translation>tolerancja dolna w mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>upper tolerance in mm</source>
        <translation>tolerancja górna w mm</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>temperature in °C (an input)</source>
        <translation>temperatura w °C (wielkość wejściowa)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>plane</source>
        <translation>płaszczyzna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line</source>
        <translation>prosta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>circle</source>
        <translation>okrąg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sphere</source>
        <translation>sfera</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cylinder</source>
        <translation>walec</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cone</source>
        <translation>stożek</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>Nominals: the %n point(s) of “%1”.</source>
        <translation>
            <numerusform>Punkty nominalne: %n punkt z „%1”.</numerusform>
            <numerusform>Punkty nominalne: %n punkty z „%1”.</numerusform>
            <numerusform>Punkty nominalne: %n punktów z „%1”.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>radius %1 mm, </source>
        <translation>promień %1 mm, </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 fitted to %n point(s): %2form %3 mm, rmse %4 mm.</source>
        <translation>
            <numerusform>%1 (dopasowanie do %n punktu): %2kształt %3 mm, RMSE %4 mm.</numerusform>
            <numerusform>%1 (dopasowanie do %n punktów): %2kształt %3 mm, RMSE %4 mm.</numerusform>
            <numerusform>%1 (dopasowanie do %n punktów): %2kształt %3 mm, RMSE %4 mm.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n stray point(s) left out of the fit.</source>
        <translation>
            <numerusform>%n odstający punkt pominięty w dopasowaniu.</numerusform>
            <numerusform>%n odstające punkty pominięte w dopasowaniu.</numerusform>
            <numerusform>%n odstających punktów pominiętych w dopasowaniu.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source> The points cover a cap of half angle %1°.</source>
        <translation> Punkty pokrywają czaszę o kącie połówkowym %1°.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> The points cover an arc of %1°.</source>
        <translation> Punkty pokrywają łuk %1°.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Badly conditioned: the noise of the points is amplified %1 times in the element.</source>
        <translation>Źle uwarunkowane: szum punktów jest wzmocniony %1 razy w elemencie.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Weakly conditioned: the noise of the points is amplified %1 times in the element.</source>
        <translation>Słabo uwarunkowane: szum punktów jest wzmocniony %1 razy w elemencie.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Skip &amp;unreadable rows</source>
        <translation>Pomiń &amp;nieczytelne wiersze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DMIS tolerance actuals</source>
        <translation>Wartości rzeczywiste tolerancji DMIS</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cop&amp;y the file into the project (data folder)</source>
        <translation>S&amp;kopiuj plik do projektu (folder data)</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+259"/>
        <source>Import data</source>
        <translation>Import danych</translation>
    </message>
    <message>
        <location line="-246"/>
        <source>Lines before the column names, skipped whatever they hold (an instrument&apos;s preamble)</source>
        <translation>Wiersze przed nazwami kolumn, pomijane bez względu na treść (nagłówek przyrządu)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What starts a comment line before the column names</source>
        <translation>Czym zaczyna się wiersz komentarza przed nazwami kolumn</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Leave out the rows listed under the preview; the project keeps this setting and the readers count the rows they leave out. Off: the first unreadable row is an error.</source>
        <translation>Pomiń wiersze wymienione pod podglądem; projekt zapamiętuje to ustawienie, a czytniki liczą pominięte wiersze. Wyłączone: pierwszy nieczytelny wiersz jest błędem.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>auto (nearer the nominal: the actual value)</source>
        <translation>automatycznie (bliżej wartości nominalnej: wartość rzeczywista)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deviation (actual − nominal)</source>
        <translation>odchyłka (rzeczywista − nominalna)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>actual value</source>
        <translation>wartość rzeczywista</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>plain (actual − nominal)</source>
        <translation>zwykły (rzeczywista − nominalna)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>follows the nominal&apos;s sign</source>
        <translation>zgodny ze znakiem wartości nominalnej</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;Import</source>
        <translation>&amp;Importuj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Browse…</source>
        <translation>Prze&amp;glądaj…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;File:</source>
        <translation>&amp;Plik:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Kind:</source>
        <translation>&amp;Rodzaj:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Id:</source>
        <translation>I&amp;dentyfikator:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The measured part (MeasurementResults) of the QIF file whose features become the probe points</source>
        <translation>Zmierzona część (MeasurementResults) pliku QIF, której elementy stają się punktami pomiarowymi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Measured &amp;part:</source>
        <translation>Zmierzona &amp;część:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The MTConnect log is resampled every this many seconds: each cell holds the last value at or before its time (empty while UNAVAILABLE)</source>
        <translation>Dziennik MTConnect jest próbkowany co tyle sekund: każda komórka zawiera ostatnią wartość w chwili lub przed chwilą jej czasu (pusta, dopóki UNAVAILABLE)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sample &amp;interval:</source>
        <translation>Interwał &amp;próbkowania:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>How the file is read</source>
        <translation>Jak plik jest odczytywany</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Delimiter:</source>
        <translation>&amp;Separator:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Decimal &amp;mark:</source>
        <translation>Znak dzi&amp;esiętny:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Comment prefix:</source>
        <translation>Prefiks &amp;komentarza:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Lines before the header:</source>
        <translation>&amp;Wiersze przed nagłówkiem:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Found:</source>
        <translation>Wykryto:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TA &amp;value is:</source>
        <translation>&amp;Wartość TA to:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TA si&amp;gn:</source>
        <translation>&amp;Znak TA:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Column in the file</source>
        <translation>Kolumna w pliku</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>First value</source>
        <translation>Pierwsza wartość</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Read as</source>
        <translation>Czytaj jako</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Columns</source>
        <translation>Kolumny</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Give a column the name the readers look for (time_s, disp_z_um, qx, x_cmd_mm, …); empty: the name in the file. The project stores this mapping, not a converted copy.</source>
        <translation>Nadaj kolumnie nazwę, której szukają czytniki (time_s, disp_z_um, qx, x_cmd_mm, …); puste: nazwa z pliku. Projekt zapisuje to przyporządkowanie, a nie przekonwertowaną kopię.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preview (first %1 rows)</source>
        <translation>Podgląd (pierwsze %1 wierszy)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+613"/>
        <source>Rows that cannot be read:</source>
        <translation>Wiersze, których nie można odczytać:</translation>
    </message>
    <message>
        <location line="-549"/>
        <source>Copy the file to the project&apos;s data folder as &lt;id&gt;.&lt;extension&gt; and refer to the copy; the import never overwrites a file there</source>
        <translation>Skopiuj plik do folderu data projektu jako &lt;id&gt;.&lt;rozszerzenie&gt; i odwołuj się do kopii; import nigdy nie nadpisuje tam pliku</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the project first: the copy goes into the project&apos;s folder</source>
        <translation>Najpierw zapisz projekt: kopia trafia do folderu projektu</translation>
    </message>
    <message>
        <location line="+61"/>
        <location line="+6"/>
        <source>All files (*)</source>
        <translation>Wszystkie pliki (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data files (*.csv *.txt *.tsv *.json *.dmi *.dms *.dmis *.xml *.qif *.QIF *.dfq *.DFQ *.stl *.STL)</source>
        <translation>Pliki danych (*.csv *.txt *.tsv *.json *.dmi *.dms *.dmis *.xml *.qif *.QIF *.dfq *.DFQ *.stl *.STL)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: cannot read the file (%2)</source>
        <translation>%1: nie można odczytać pliku (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the file is larger than 256 MiB</source>
        <translation>%1: plik jest większy niż 256 MiB</translation>
    </message>
    <message numerus="yes">
        <location line="+187"/>
        <source>Read the %n selected files as one DMIS &amp;series (one dataset, one file per workpiece)</source>
        <translation>
            <numerusform>Wczytaj %n wybrany plik jako jedną &amp;serię DMIS (jeden zbiór danych, jeden plik na przedmiot)</numerusform>
            <numerusform>Wczytaj %n wybrane pliki jako jedną &amp;serię DMIS (jeden zbiór danych, jeden plik na przedmiot)</numerusform>
            <numerusform>Wczytaj %n wybranych plików jako jedną &amp;serię DMIS (jeden zbiór danych, jeden plik na przedmiot)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Also: %1</source>
        <translation>Także: %1</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>as in the file</source>
        <translation>jak w pliku</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Line</source>
        <translation>Wiersz</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>DMIS output: add a setup model to the project to preview the deviations read with these settings.</source>
        <translation>Wynik DMIS: dodaj do projektu model ustawczy, aby zobaczyć podgląd odchyłek odczytanych z tymi ustawieniami.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Dimension</source>
        <translation>Wymiar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Deviation (mm)</source>
        <translation>Odchyłka (mm)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>DMIS output read against the setup model “%1”.</source>
        <translation>Wynik DMIS odczytany względem modelu ustawczego „%1”.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DMIS series of %1 files read against the setup model “%2”: the mean deviation over the workpieces.</source>
        <translation>Seria DMIS z %1 plików odczytana względem modelu ustawienia „%2”: średnia odchyłka po przedmiotach.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>DMIS output; read against the setup model “%1”: %2</source>
        <translation>Wynik DMIS; odczyt względem modelu ustawczego „%1”: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>MTConnect log resampled every %1 s (zero-order hold: the last value at or before each time): %2 rows, %3 sample columns; %4 data items are not columns (events, conditions, no numbers).</source>
        <translation>Dziennik MTConnect próbkowany co %1 s (ekstrapolator zerowego rzędu: ostatnia wartość w chwili lub przed każdą chwilą): %2 wierszy, %3 kolumn próbek; %4 elementów danych nie jest kolumnami (zdarzenia, stany, brak liczb).</translation>
    </message>
    <message numerus="yes">
        <location line="+39"/>
        <source>%n feature row(s)</source>
        <translation>
            <numerusform>%n wiersz cech</numerusform>
            <numerusform>%n wiersze cech</numerusform>
            <numerusform>%n wierszy cech</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n row(s)</source>
        <translation>
            <numerusform>%n wiersz</numerusform>
            <numerusform>%n wiersze</numerusform>
            <numerusform>%n wierszy</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: read as %2, %3.</source>
        <translation>%1: odczytano jako %2, %3.</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Choose a file to import.</source>
        <translation>Wybierz plik do importu.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Not a CSV file: read as %1 (no delimiter, decimal mark or column mapping).</source>
        <translation>To nie jest plik CSV: czytany jako %1 (bez separatora, znaku dziesiętnego i przyporządkowania kolumn).</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>detect (%1)</source>
        <translation>wykryj (%1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Rows that cannot be read (%1): tick “Skip unreadable rows” to import without them.</source>
        <translation>Wiersze, których nie można odczytać (%1): zaznacz „Pomiń nieczytelne wiersze”, aby zaimportować bez nich.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Rows that cannot be read (%1), left out:</source>
        <translation>Wiersze, których nie można odczytać (%1), pominięte:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (detected)</source>
        <translation>%1 (wykryto)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>delimiter %1 · decimal mark %2 · header in line %3 (%4 columns) · comment lines: %5 · data rows: %6</source>
        <translation>separator %1 · znak dziesiętny %2 · nagłówek w wierszu %3 (%4 kolumn) · wiersze komentarza: %5 · wiersze danych: %6</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Nominals: the closest points of the CAD part “%1”; the matching moves the points onto it at each posture (closed form or minimum zone).</source>
        <translation>Punkty nominalne: najbliższe punkty części CAD „%1”; dopasowanie rzutuje punkty na nią przy każdym położeniu (rozwiązanie zamknięte lub strefa minimalna).</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1: already exists; an embedded copy never overwrites a file (choose another id)</source>
        <translation>%1: już istnieje; osadzona kopia nigdy nie nadpisuje pliku (wybierz inny identyfikator)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ready to import as %1 “%2”.</source>
        <translation>Gotowe do importu jako %1 „%2”.</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>The %n file(s) are one DMIS series: one workpiece per file.</source>
        <translation>
            <numerusform>%n plik to jedna seria DMIS: jeden przedmiot na plik.</numerusform>
            <numerusform>%n pliki to jedna seria DMIS: jeden przedmiot na plik.</numerusform>
            <numerusform>%n plików to jedna seria DMIS: jeden przedmiot na plik.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n unreadable row(s) will be left out.</source>
        <translation>
            <numerusform>%n nieczytelny wiersz zostanie pominięty.</numerusform>
            <numerusform>%n nieczytelne wiersze zostaną pominięte.</numerusform>
            <numerusform>%n nieczytelnych wierszy zostanie pominiętych.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The file is copied to %1.</source>
        <translation>Plik zostanie skopiowany do %1.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Nominals of the measured points</source>
        <translation>Punkty nominalne zmierzonych punktów</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a fitted element</source>
        <translation>dopasowanego elementu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a second measurement of the part</source>
        <translation>drugiego pomiaru części</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a CAD part</source>
        <translation>części CAD</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no normals (positions only)</source>
        <translation>bez normalnych (tylko położenia)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>free (fitted)</source>
        <translation>swobodny (dopasowany)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A calibrated or drawing radius the element keeps; free: fitted</source>
        <translation>Promień wzorcowy lub z rysunku, który element zachowuje; swobodny: dopasowany</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>least squares</source>
        <translation>najmniejsze kwadraty</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>minimum zone</source>
        <translation>strefa minimalna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Bore or hole (material outside)</source>
        <translation>&amp;Otwór (materiał na zewnątrz)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The normals point out of the material: into a bore, out of a shaft or ball</source>
        <translation>Normalne wskazują na zewnątrz materiału: do wnętrza otworu, na zewnątrz wałka lub kuli</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Leave stray points out of the fit</source>
        <translation>Pomiń punkty odstające w dopasowaniu</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Import the part&apos;s STL file first</source>
        <translation>Najpierw zaimportuj plik STL części</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>by id</source>
        <translation>według id</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>by order</source>
        <translation>według kolejności</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Import the first measurement of the part first</source>
        <translation>Najpierw zaimportuj pierwszy pomiar części</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Measurement:</source>
        <translation>&amp;Pomiar:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;From:</source>
        <translation>&amp;Z:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Radius:</source>
        <translation>&amp;Promień:</translation>
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
        <translation>zmierzony, pętla przeciwnie do ruchu wskazówek zegara</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured, CW loop</source>
        <translation>zmierzony, pętla zgodnie z ruchem wskazówek zegara</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>expected after compensation</source>
        <translation>oczekiwany po kompensacji</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nominal R %1 mm</source>
        <translation>nominalny R %1 mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nominal circle (radius not in the file, drawn as %1 mm)</source>
        <translation>okrąg nominalny (promienia brak w pliku, narysowany jako %1 mm)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>plotted radius = R + k × radial deviation, k = %1; rings every %2 µm</source>
        <translation>promień na wykresie = R + k × odchyłka promieniowa, k = %1; okręgi co %2 µm</translation>
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
        <translation>okrąg nominalny</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>measured CCW</source>
        <translation>zmierzony, w lewo (CCW)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>measured CW</source>
        <translation>zmierzony, w prawo (CW)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>compensated references</source>
        <translation>skompensowane wartości zadane</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>expected after</source>
        <translation>oczekiwany po</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>deviations from the nominal point × %1</source>
        <translation>odchyłki od nominału × %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>one point beyond the control limits</source>
        <translation>jeden punkt poza granicami kontrolnymi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nine in a row on one side of the centre line</source>
        <translation>dziewięć kolejnych po jednej stronie linii centralnej</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>six in a row steadily increasing or decreasing</source>
        <translation>sześć kolejnych stale rosnących lub malejących</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fourteen in a row alternating up and down</source>
        <translation>czternaście kolejnych naprzemiennie w górę i w dół</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>two of three beyond 2 σ on the same side</source>
        <translation>dwa z trzech poza 2 σ po tej samej stronie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>four of five beyond 1 σ on the same side</source>
        <translation>cztery z pięciu poza 1 σ po tej samej stronie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fifteen in a row within 1 σ</source>
        <translation>piętnaście kolejnych w granicach 1 σ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>eight in a row beyond 1 σ on either side</source>
        <translation>osiem kolejnych poza 1 σ po obu stronach</translation>
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
        <translation>X-średnie</translation>
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
        <translation>%1 %2 przy %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none broken</source>
        <translation>żadna nie złamana</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (limits from subgroups 1–%1)</source>
        <translation> (granice z podgrup 1–%1)</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>X chart (individual values)</source>
        <translation>karta X (wartości indywidualne)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MR chart (moving range of 2)</source>
        <translation>karta MR (ruchomy rozstęp z 2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X-bar chart (subgroups of %1)</source>
        <translation>Karta X-średnie (podgrupy po %1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R chart (subgroups of %1)</source>
        <translation>Karta R (podgrupy po %1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, limits from subgroups 1–%1</source>
        <translation>, granice z podgrup 1–%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>moving range</source>
        <translation>ruchomy rozstęp</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>subgroup</source>
        <translation>podgrupa</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>subgroup mean</source>
        <translation>średnia</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>subgroup range</source>
        <translation>rozstęp</translation>
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
        <translation>faza I</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>phase II</source>
        <translation>faza II</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>Histogram</source>
        <translation>Histogram</translation>
    </message>
    <message>
        <location line="-120"/>
        <location line="+127"/>
        <source>value</source>
        <translation>wartość</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>count</source>
        <translation>liczność</translation>
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
        <translation>nominalna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean</source>
        <translation>średnia</translation>
    </message>
</context>
<context>
    <name>metrofit::KinematicsPage</name>
    <message>
        <location filename="../app/gui/kinematicspage.cpp" line="+179"/>
        <source>&amp;Identify</source>
        <translation>&amp;Identyfikuj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Compensate</source>
        <translation>&amp;Kompensuj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;G-code…</source>
        <translation>Eksportuj &amp;G-code…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;STEP-NC…</source>
        <translation>Eksportuj &amp;STEP-NC…</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Identify the actuator origin and orientation errors of the circular test (Levenberg-Marquardt, standard errors from the residuals) (F5)</source>
        <translation>Identyfikuj błędy początku i orientacji napędów z testu kołowego (Levenberg-Marquardt, błędy standardowe z residuów) (F5)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Compensated references for the nominal circle (Eq. 15 with the identified errors), and what they give (Ctrl+K)</source>
        <translation>Skompensowane wartości zadane dla okręgu nominalnego (równ. 15 ze zidentyfikowanymi błędami) i ich efekt (Ctrl+K)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the compensated references as G-code (G01 blocks)</source>
        <translation>Zapisz skompensowane wartości zadane jako G-code (bloki G01)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the compensated references as a STEP-NC (ISO 10303-21) file</source>
        <translation>Zapisz skompensowane wartości zadane jako plik STEP-NC (ISO 10303-21)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+127"/>
        <source>error</source>
        <translation>błąd</translation>
    </message>
    <message>
        <location line="-127"/>
        <source>identified</source>
        <translation>wyznaczony</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>std. error</source>
        <translation>błąd std.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>simulated</source>
        <translation>symulowany</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>max radial deviation</source>
        <translation>maks. odchyłka promieniowa</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&lt;b&gt;Identified errors&lt;/b&gt; (origin in µm, angles in deg)</source>
        <translation>&lt;b&gt;Zidentyfikowane błędy&lt;/b&gt; (początek w µm, kąty w °)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Effects added with Apply on the Diagnosis page: the identification, the compensated references and their exports include them. Undo the Apply to use the declared model again.</source>
        <translation>Efekty dodane przyciskiem „Zastosuj do modelu” na stronie Diagnoza: uwzględniają je identyfikacja, skompensowane wartości zadane i ich eksporty. Cofnij zastosowanie, aby ponownie użyć zadeklarowanego modelu.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;b&gt;Compensation&lt;/b&gt; of the nominal circle</source>
        <translation>&lt;b&gt;Kompensacja&lt;/b&gt; okręgu nominalnego</translation>
    </message>
    <message>
        <location line="+207"/>
        <source>cause</source>
        <translation>przyczyna</translation>
    </message>
    <message>
        <location line="-189"/>
        <source>&amp;Path</source>
        <translation>&amp;Tor</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Se&amp;ries:</source>
        <translation>Se&amp;ria:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The measured series charted (a feature series or a CMM report, one value per part; studies.kinematics.spc.dataset)</source>
        <translation>Przedstawiona seria pomiarowa (seria cech lub raport CMM, jedna wartość na część; studies.kinematics.spc.dataset)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>C&amp;haracteristic:</source>
        <translation>&amp;Cecha:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The column of the series charted (studies.kinematics.spc.column)</source>
        <translation>Przedstawiona kolumna serii (studies.kinematics.spc.column)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>S&amp;ubgroup:</source>
        <translation>Po&amp;dgrupa:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Consecutive parts per subgroup of the X-bar/R chart (studies.kinematics.spc.subgroup)</source>
        <translation>Kolejne części w podgrupie karty X-średnie/R (studies.kinematics.spc.subgroup)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>none</source>
        <translation>brak</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;LSL:</source>
        <translation>D&amp;GT:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lower specification limit, in the series&apos; unit (studies.kinematics.spc.lsl)</source>
        <translation>Dolna granica tolerancji, w jednostce serii (studies.kinematics.spc.lsl)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Upper specification limit, in the series&apos; unit (studies.kinematics.spc.usl)</source>
        <translation>Górna granica tolerancji, w jednostce serii (studies.kinematics.spc.usl)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Nominal:</source>
        <translation>&amp;Nominał:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The desired value, in the series&apos; unit (studies.kinematics.spc.nominal)</source>
        <translation>Wartość zadana, w jednostce serii (studies.kinematics.spc.nominal)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Choose the SPC characteristic</source>
        <translation>Wybierz cechę SPC</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Change the SPC subgroup size</source>
        <translation>Zmień wielkość podgrupy SPC</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export Q-DAS &amp;DFQ…</source>
        <translation>Eksportuj Q-DAS &amp;DFQ…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>S&amp;PC</source>
        <translation>S&amp;PC</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>from SPC</source>
        <translation>z SPC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>from circular test</source>
        <translation>z testu kołowego</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>plane</source>
        <translation>płaszczyzna</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>u axis angle a (°)</source>
        <translation>kąt osi u a (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>v axis angle b (°)</source>
        <translation>kąt osi v b (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>squareness b − a (°)</source>
        <translation>prostopadłość b − a (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>± std. error (°)</source>
        <translation>± błąd standardowy (°)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMS (µm)</source>
        <translation>RMS (µm)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Choose the edge along X</source>
        <translation>Wybór krawędzi wzdłuż X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the edge along Y</source>
        <translation>Wybór krawędzi wzdłuż Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the XY circular test</source>
        <translation>Wybór testu kołowego XY</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the YZ circular test</source>
        <translation>Wybór testu kołowego YZ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the ZX circular test</source>
        <translation>Wybór testu kołowego ZX</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Edge along &amp;X:</source>
        <translation>Kr&amp;awędź wzdłuż X:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Edge along &amp;Y:</source>
        <translation>K&amp;rawędź wzdłuż Y:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>XY circular &amp;test:</source>
        <translation>Test k&amp;ołowy XY:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y&amp;Z circular test:</source>
        <translation>Test kołowy Y&amp;Z:</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ZX circ&amp;ular test:</source>
        <translation>Test kołowy Z&amp;X:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The edge machined along X and measured (feature series, CSV position_mm,deviation_mm)</source>
        <translation>Krawędź obrobiona wzdłuż X i zmierzona (seria cechy, CSV position_mm,deviation_mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The edge machined along Y and measured (feature series, CSV position_mm,deviation_mm)</source>
        <translation>Krawędź obrobiona wzdłuż Y i zmierzona (seria cechy, CSV position_mm,deviation_mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular test in the XY plane (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)</source>
        <translation>Test kołowy w płaszczyźnie XY (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular test in the YZ plane (CSV y_cmd_mm,z_cmd_mm,y_meas_mm,z_meas_mm)</source>
        <translation>Test kołowy w płaszczyźnie YZ (CSV y_cmd_mm,z_cmd_mm,y_meas_mm,z_meas_mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circular test in the ZX plane (CSV z_cmd_mm,x_cmd_mm,z_meas_mm,x_meas_mm)</source>
        <translation>Test kołowy w płaszczyźnie ZX (CSV z_cmd_mm,x_cmd_mm,z_meas_mm,x_meas_mm)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Save &amp;DFQ…</source>
        <translation>Zapisz &amp;DFQ…</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>&amp;Actuators</source>
        <translation>&amp;Napędy</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The radial deviation of both runs fitted to the signature of each cause, after the centre and radius of each run (as metrofit-cli kinematic identify writes it under &quot;causes&quot;). Share: the part of the radial deviation&apos;s variance the cause explains. Grey: within the noise (at most three standard errors).</source>
        <translation>Odchylenie promieniowe obu przebiegów dopasowane do sygnatury każdej przyczyny, po środku i promieniu każdego przebiegu (tak jak metrofit-cli kinematic identify zapisuje je w &quot;causes&quot;). Udział: część wariancji odchylenia promieniowego, którą wyjaśnia przyczyna. Szare: w granicach szumu (najwyżej trzy błędy standardowe).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>value (µm)</source>
        <translation>wartość (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>± std. error (µm)</source>
        <translation>± błąd standardowy (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>share (%)</source>
        <translation>udział (%)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Ballbar</source>
        <translation>&amp;Ballbar</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>C&amp;ircular test:</source>
        <translation>Test kołow&amp;y:</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Compensate</source>
        <translation>Kompensuj</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+100"/>
        <source>(none)</source>
        <translation>(brak)</translation>
    </message>
    <message>
        <location line="-90"/>
        <source>%1 (not a dataset id)</source>
        <translation>%1 (to nie jest identyfikator zbioru danych)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (not in the project)</source>
        <translation>%1 (nie ma w projekcie)</translation>
    </message>
    <message>
        <location line="+146"/>
        <source>Remove the SPC series</source>
        <translation>Usuń serię SPC</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>“%1” has no column of numbers to chart.</source>
        <translation>„%1” nie ma kolumny liczb do przedstawienia.</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+2"/>
        <location line="+2"/>
        <source>Choose the SPC series</source>
        <translation>Wybierz serię SPC</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Not a number: %1</source>
        <translation>To nie jest liczba: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Give both specification limits (LSL and USL), or neither; nothing is written until then.</source>
        <translation>Podaj obie granice tolerancji (DGT i GGT) albo żadnej; do tego czasu nic nie zostanie zapisane.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The lower specification limit must be below the upper one.</source>
        <translation>Dolna granica tolerancji musi być poniżej górnej.</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+2"/>
        <source>Change the SPC limits</source>
        <translation>Zmień granice SPC</translation>
    </message>
    <message>
        <location line="+78"/>
        <source>This project has no circular test. Add a dataset of kind &quot;circular_test&quot; (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm, one loop CCW then one CW), e.g. made by metrofit-cli simulate circular.</source>
        <translation>Ten projekt nie zawiera testu kołowego. Dodaj zbiór danych rodzaju „circular_test” (CSV x_cmd_mm,y_cmd_mm,x_meas_mm,y_meas_mm, jedna pętla przeciwnie do ruchu wskazówek zegara, potem jedna zgodnie), np. utworzony przez metrofit-cli simulate circular.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No circular test in this project: only the SPC tab is available. %1</source>
        <translation>Brak testu okrągłości w tym projekcie: dostępna jest tylko karta SPC. %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import a circular test (Ctrl+I) for the path, actuators and ballbar tabs.</source>
        <translation>Zaimportuj test okrągłości (Ctrl+I), aby użyć kart Tor, Napędy i Ballbar.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Cannot identify this circular test:
%1</source>
        <translation>Nie można zidentyfikować tego testu kołowego:
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
        <translation>CCW</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CW</source>
        <translation>CW</translation>
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
            <numerusform>Punkty: %1, okrąg nominalny R %2 mm wokół (%3; %4) mm; %n pętla.</numerusform>
            <numerusform>Punkty: %1, okrąg nominalny R %2 mm wokół (%3; %4) mm; %n pętle.</numerusform>
            <numerusform>Punkty: %1, okrąg nominalny R %2 mm wokół (%3; %4) mm; %n pętli.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Effects applied on the Diagnosis page belong to the circular test %1 (the one the diagnosis ran on); this test uses the declared model.</source>
        <translation>Efekty zastosowane na stronie Diagnoza należą do testu kołowego %1 (tego, na którym przeprowadzono diagnozę); ten test używa zadeklarowanego modelu.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Includes applied effects: %1</source>
        <translation>Zawiera zastosowane efekty: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+136"/>
        <source>origin x (µm)</source>
        <translation>początek x (µm)</translation>
    </message>
    <message>
        <location line="-134"/>
        <source>Where the tool is at command 0 (Oyr of Eq. 9), x</source>
        <translation>Gdzie znajduje się narzędzie przy wartości zadanej 0 (Oyr z równ. 9), x</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+134"/>
        <source>origin y (µm)</source>
        <translation>początek y (µm)</translation>
    </message>
    <message>
        <location line="-132"/>
        <source>Where the tool is at command 0 (Oyr of Eq. 9), y</source>
        <translation>Gdzie znajduje się narzędzie przy wartości zadanej 0 (Oyr z równ. 9), y</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+132"/>
        <source>X axis angle a (deg)</source>
        <translation>kąt osi X a (stopnie)</translation>
    </message>
    <message>
        <location line="-130"/>
        <source>The X actuator moves along (cos a, sin a); counter-clockwise positive</source>
        <translation>Napęd X porusza się wzdłuż (cos a, sin a); dodatnio przeciwnie do ruchu wskazówek zegara</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+130"/>
        <source>Y axis angle b (deg)</source>
        <translation>kąt osi Y b (stopnie)</translation>
    </message>
    <message>
        <location line="-128"/>
        <source>The Y actuator moves along (-sin b, cos b); counter-clockwise positive</source>
        <translation>Napęd Y porusza się wzdłuż (-sin b, cos b); dodatnio przeciwnie do ruchu wskazówek zegara</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+128"/>
        <source>squareness b − a (deg)</source>
        <translation>prostopadłość b − a (stopnie)</translation>
    </message>
    <message>
        <location line="-126"/>
        <source>The angle between the axes is 90° + (b − a)</source>
        <translation>Kąt między osiami wynosi 90° + (b − a)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMS residual (µm)</source>
        <translation>residuum RMS (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Root mean square of the residual distances after identification, with the applied effects</source>
        <translation>Średnia kwadratowa odległości resztkowych po identyfikacji, z zastosowanymi efektami</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Root mean square of the residual distances after identification</source>
        <translation>Średnia kwadratowa odległości resztkowych po identyfikacji</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>iterations</source>
        <translation>iteracje</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS, declared model only (µm)</source>
        <translation>RMS, tylko zadeklarowany model (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The residual of the declared model (origin and axis angles, no applied effects)</source>
        <translation>Residuum zadeklarowanego modelu (początek i kąty osi, bez zastosowanych efektów)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Path (XY)</source>
        <translation>Tor (XY)</translation>
    </message>
    <message>
        <location line="-136"/>
        <location line="+155"/>
        <source>No SPC series is chosen: choose the measured series and its characteristic above (a feature series or a CMM report, imported with File › Import data, Ctrl+I).</source>
        <translation>Nie wybrano serii SPC: wybierz powyżej serię pomiarową i jej cechę (seria cech lub raport CMM, zaimportowane przez Plik › Importuj dane, Ctrl+I).</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&lt;b&gt;Ballbar breakdown&lt;/b&gt;: not available (%1)</source>
        <translation>&lt;b&gt;Rozkład ballbar&lt;/b&gt;: niedostępny (%1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&lt;b&gt;Ballbar breakdown&lt;/b&gt; (ranked by share)</source>
        <translation>&lt;b&gt;Rozkład ballbar&lt;/b&gt; (według udziału)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;b&gt;Ballbar breakdown&lt;/b&gt; (ranked by share; one direction: no reversal causes)</source>
        <translation>&lt;b&gt;Rozkład ballbar&lt;/b&gt; (według udziału; jeden kierunek: bez przyczyn nawrotnych)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Within the noise: |%1 µm| is at most three standard errors (%2 µm)</source>
        <translation>W granicach szumu: |%1 µm| to najwyżej trzy błędy standardowe (%2 µm)</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>&lt;b&gt;From SPC to compensation&lt;/b&gt;: choose the edges machined along X and along Y above (feature series, CSV position_mm,deviation_mm in mm, e.g. made by metrofit-cli simulate edge).</source>
        <translation>&lt;b&gt;Od SPC do kompensacji&lt;/b&gt;: wybierz powyżej krawędzie obrobione wzdłuż X i wzdłuż Y (serie cech, CSV position_mm,deviation_mm w mm, np. utworzone przez metrofit-cli simulate edge).</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>&lt;b&gt;Three axes&lt;/b&gt;: choose the circular tests in the XY, YZ and ZX planes above (made e.g. by metrofit-cli simulate circular --plane yz).</source>
        <translation>&lt;b&gt;Trzy osie&lt;/b&gt;: wybierz powyżej testy kołowe w płaszczyznach XY, YZ i ZX (utworzone np. przez metrofit-cli simulate circular --plane yz).</translation>
    </message>
    <message>
        <location line="-268"/>
        <location line="+110"/>
        <source>Radial deviation (polar, magnified)</source>
        <translation>Odchyłka promieniowa (biegunowo, powiększona)</translation>
    </message>
    <message>
        <location line="-693"/>
        <source>USL:</source>
        <translation>GGT:</translation>
    </message>
    <message>
        <location line="+502"/>
        <source>The kinematics study&apos;s settings are invalid; nothing is run until they are corrected (Undo, or the project file):
%1</source>
        <translation>Ustawienia badania kinematyki są nieprawidłowe; nic nie zostanie uruchomione, dopóki nie zostaną poprawione (Cofnij lub plik projektu):
%1</translation>
    </message>
    <message>
        <location line="+194"/>
        <source>measured</source>
        <translation>zmierzony</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Write the feature series with its limits as a Q-DAS DFQ file (the K-field file SPC packages import)</source>
        <translation>Zapisz serię cechy wraz z granicami jako plik Q-DAS DFQ (plik pól K importowany przez programy SPC)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The kinematics study names no SPC series to export</source>
        <translation>Badanie kinematyki nie wskazuje serii SPC do eksportu</translation>
    </message>
    <message>
        <location line="-150"/>
        <location line="+155"/>
        <source>Cannot chart the SPC series:
%1</source>
        <translation>Nie można wykreślić serii SPC:
%1</translation>
    </message>
    <message numerus="yes">
        <location line="+57"/>
        <source>compensation applied: %n of 4 line parameters beyond ± k standard errors (k = %1), residuals in control</source>
        <translation>
            <numerusform>kompensacja zastosowana: %n z 4 parametrów prostej poza ± k błędów standardowych (k = %1), residua pod kontrolą</numerusform>
            <numerusform>kompensacja zastosowana: %n z 4 parametrów prostej poza ± k błędów standardowych (k = %1), residua pod kontrolą</numerusform>
            <numerusform>kompensacja zastosowana: %n z 4 parametrów prostej poza ± k błędów standardowych (k = %1), residua pod kontrolą</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not compensated: the residuals about a regression line are out of control (special causes first)</source>
        <translation>bez kompensacji: residua wokół prostej regresji są poza kontrolą (najpierw usunąć przyczyny specjalne)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not compensated: no slope or intercept beyond ± k standard errors (random scatter)</source>
        <translation>bez kompensacji: żadne nachylenie ani wyraz wolny nie wykracza poza ± k błędów standardowych (rozrzut losowy)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;b&gt;From SPC to compensation&lt;/b&gt; (IEEE Access, kinematic compensation algorithm): the offset angle of the regression line of the edge along X is the X actuator&apos;s angle a, minus that of the edge along Y is b (Eq. 9), the intercepts give the origin; %1.</source>
        <translation>&lt;b&gt;Od SPC do kompensacji&lt;/b&gt; (IEEE Access, algorytm kompensacji kinematycznej): kąt przesunięcia prostej regresji krawędzi wzdłuż X jest kątem a napędu X, ujemny kąt krawędzi wzdłuż Y jest kątem b (równ. 9), wyrazy wolne dają początek; %1.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>offset angle, edge along X (°)</source>
        <translation>kąt przesunięcia, krawędź wzdłuż X (°)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+4"/>
        <source>atan(slope) of the deviation against the position (Fig. 10); ± %1°</source>
        <translation>atan(nachylenia) odchyłki względem położenia (rys. 10); ± %1°</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>offset angle, edge along Y (°)</source>
        <translation>kąt przesunięcia, krawędź wzdłuż Y (°)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>largest correction (µm)</source>
        <translation>największa korekta (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest |reference − nominal point| of the Eq. 15 references for the nominal circle</source>
        <translation>Największe |wartość zadana − punkt nominalny| wartości zadanych wg równ. 15 dla okręgu nominalnego</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>circular test model: before → after (µm)</source>
        <translation>model testu kołowego: przed → po (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The machine identified from the circular test (an independent estimate) on the nominal circle and on the references derived from SPC: largest distance from the nominal points</source>
        <translation>Maszyna zidentyfikowana z testu kołowego (niezależna estymacja) na okręgu nominalnym i na wartościach zadanych wyznaczonych z SPC: największa odległość od punktów nominalnych</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&lt;b&gt;From SPC to compensation&lt;/b&gt;: cannot derive the actuator errors:&lt;br&gt;%1</source>
        <translation>&lt;b&gt;Od SPC do kompensacji&lt;/b&gt;: nie można wyznaczyć błędów napędów:&lt;br&gt;%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&lt;b&gt;Three axes&lt;/b&gt; from circular tests in XY, YZ and ZX: origin (%1, %2, %3) µm ± %4 µm, RMS residual %5 µm, %6 points.</source>
        <translation>&lt;b&gt;Trzy osie&lt;/b&gt; z testów kołowych w XY, YZ i ZX: początek (%1; %2; %3) µm ± %4 µm, residuum RMS %5 µm, punkty: %6.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>In the plane (u, v) the u actuator moves along (cos a, sin a), the v actuator along (−sin b, cos b); the angle between them is 90° + (b − a)</source>
        <translation>W płaszczyźnie (u, v) napęd u porusza się wzdłuż (cos a, sin a), napęd v wzdłuż (−sin b, cos b); kąt między nimi wynosi 90° + (b − a)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&lt;b&gt;Three axes&lt;/b&gt;: cannot identify:&lt;br&gt;%1</source>
        <translation>&lt;b&gt;Trzy osie&lt;/b&gt;: identyfikacja niemożliwa:&lt;br&gt;%1</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>The stored result (computed %1) is out of date: the kinematics settings changed since. Compensate (Ctrl+K) to compute it with these settings.</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: ustawienia kinematyki zmieniły się od tego czasu. Kompensuj (Ctrl+K), aby obliczyć go z tymi ustawieniami.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the circular test&apos;s file changed since. Compensate (Ctrl+K) to compute it on the test as it is now.</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: plik testu kołowego zmienił się od tego czasu. Kompensuj (Ctrl+K), aby obliczyć go dla testu w obecnej postaci.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the circular test&apos;s file cannot be read.</source>
        <translation>Nie można sprawdzić zapisanego wyniku (obliczonego %1): nie można odczytać pliku testu kołowego.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>From the saved project, computed %1 with these settings on this test: identified origin (%2, %3) µm, X axis angle a %4°, Y axis angle b %5°, squareness b − a %6°, RMS residual %7 µm. Compensation: max radial deviation %8 µm measured, %9 µm expected after (RMS %10 µm), largest correction %11 µm.</source>
        <translation>Z zapisanego projektu, obliczono %1 z tymi ustawieniami dla tego testu: zidentyfikowany początek (%2; %3) µm, kąt osi X a %4°, kąt osi Y b %5°, prostopadłość b − a %6°, residuum RMS %7 µm. Kompensacja: największe odchylenie promieniowe %8 µm zmierzone, %9 µm oczekiwane po (RMS %10 µm), największa korekta %11 µm.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Simulated machine after: %1 µm.</source>
        <translation>Symulowana obrabiarka po: %1 µm.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compensate (Ctrl+K) to see the compensated path.</source>
        <translation>Kompensuj (Ctrl+K), aby zobaczyć skompensowaną ścieżkę.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>measured (before)</source>
        <translation>zmierzony (przed)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest |radial deviation| of the measured path from the nominal circle</source>
        <translation>Największa |odchyłka promieniowa| zmierzonego toru od okręgu nominalnego</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identified model, after</source>
        <translation>zidentyfikowany model, po</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The compensated references run through the identified model (Eq. 9): on the circle up to rounding</source>
        <translation>Skompensowane wartości zadane przepuszczone przez zidentyfikowany model (równ. 9): na okręgu z dokładnością do zaokrągleń</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>expected after (measured residual)</source>
        <translation>oczekiwany po (zmierzone residuum)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The measured path moved by what the references change: the residual the model does not explain (noise, unmodelled effects) stays</source>
        <translation>Zmierzony tor przesunięty o zmianę wartości zadanych: residuum niewyjaśnione przez model (szum, niemodelowane efekty) pozostaje</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>expected after, RMS distance</source>
        <translation>oczekiwany po, odległość RMS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Root mean square distance of the expected path from the nominal points (before: %1 µm)</source>
        <translation>Średnia kwadratowa odległości oczekiwanego toru od punktów nominalnych (przed: %1 µm)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>simulated machine, after</source>
        <translation>maszyna symulowana, po</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The references run through the simulated machine (the true errors of the study), noise free</source>
        <translation>Wartości zadane przepuszczone przez maszynę symulowaną (rzeczywiste błędy studium), bez szumu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>largest correction</source>
        <translation>największa korekcja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest |reference − nominal point|</source>
        <translation>Największa |wartość zadana − punkt nominalny|</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Write the two edges&apos; deviations (mm) as a Q-DAS DFQ file, two characteristics</source>
        <translation>Zapisz odchyłki (mm) obu krawędzi jako plik Q-DAS DFQ, dwie cechy</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the edges machined along X and Y first</source>
        <translation>Najpierw wybierz krawędzie obrobione wzdłuż X i Y</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Export compensated path as G-code</source>
        <translation>Eksport skompensowanego toru jako G-code</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>G-code (*.nc *.ngc *.gcode)</source>
        <translation>G-code (*.nc *.ngc *.gcode)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export G-code</source>
        <translation>Eksport G-code</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The kinematics study names no SPC series to export.</source>
        <translation>Badanie kinematyki nie wskazuje serii SPC do eksportu.</translation>
    </message>
    <message>
        <location line="+22"/>
        <location line="+5"/>
        <source>Export Q-DAS DFQ</source>
        <translation>Eksport Q-DAS DFQ</translation>
    </message>
    <message>
        <location line="-3"/>
        <location line="+30"/>
        <source>Q-DAS DFQ files (*.dfq);;All files (*)</source>
        <translation>Pliki Q-DAS DFQ (*.dfq);;Wszystkie pliki (*)</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>Choose the edges machined along X and Y first.</source>
        <translation>Najpierw wybierz krawędzie obrobione wzdłuż X i Y.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Save the edges as Q-DAS DFQ</source>
        <translation>Zapisz krawędzie jako Q-DAS DFQ</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save DFQ</source>
        <translation>Zapisz DFQ</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export compensated path as STEP-NC</source>
        <translation>Eksport skompensowanego toru jako STEP-NC</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>STEP-NC Part 21 (*.p21 *.stp)</source>
        <translation>STEP-NC Part 21 (*.p21 *.stp)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export STEP-NC</source>
        <translation>Eksport STEP-NC</translation>
    </message>
</context>
<context>
    <name>metrofit::MachineDialog</name>
    <message>
        <location filename="../app/gui/machinedialog.cpp" line="+40"/>
        <source>Head-head XFYZBA (A and B on the head; the paper&apos;s machine)</source>
        <translation>Głowica-głowica XFYZBA (A i B w głowicy; obrabiarka z publikacji)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Table-table AC (A trunnion carrying a C table)</source>
        <translation>Stół-stół AC (kołyska A z obrotowym stołem C)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Table-table BC (B trunnion carrying a C table)</source>
        <translation>Stół-stół BC (kołyska B z obrotowym stołem C)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Head-table (B swivel head, C rotary table)</source>
        <translation>Głowica-stół (głowica uchylna B, stół obrotowy C)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Head-head geometry (Eq. 12–13)</source>
        <translation>Geometria głowica-głowica (równ. 12–13)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt axis (table-table)</source>
        <translation>Oś uchylna (stół-stół)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Swivel head (head-table)</source>
        <translation>Głowica uchylna (głowica-stół)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C axis of the rotary table</source>
        <translation>Oś C stołu obrotowego</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Machine</source>
        <translation>Obrabiarka</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The kinematics the adjustment values are computed for</source>
        <translation>Kinematyka, dla której obliczane są wartości korekty</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The control the controller frame is written for</source>
        <translation>Sterowanie, dla którego zapisywany jest frame sterowania</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Topology:</source>
        <translation>&amp;Topologia:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Control:</source>
        <translation>&amp;Sterowanie:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>LX (cutter location in the A frame):</source>
        <translation>LX (położenie narzędzia w układzie A):</translation>
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
        <translation>LAB (początek układu A w układzie B):</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A point on the tilt axis at the zero position (workpiece coordinates):</source>
        <translation>Punkt na osi uchylnej w położeniu zerowym (współrzędne przedmiotu):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A point on the C axis at the zero position (workpiece coordinates):</source>
        <translation>Punkt na osi C w położeniu zerowym (współrzędne przedmiotu):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Pivot length (B axis above the tool point):</source>
        <translation>Długość wahadła (oś B nad końcem narzędzia):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Travel</source>
        <translation>Zakres ruchu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Axis</source>
        <translation>Oś</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limited</source>
        <translation>Ograniczona</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum</source>
        <translation>Maksimum</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>always</source>
        <translation>zawsze</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Check the adjustment value S%1 against a travel</source>
        <translation>Sprawdzaj wartość korekty S%1 względem zakresu ruchu</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&amp;Preset</source>
        <translation>&amp;Ustawienie domyślne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The topology&apos;s default geometry and travel</source>
        <translation>Domyślna geometria i zakres ruchu topologii</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Import…</source>
        <translation>&amp;Importuj…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read a machine JSON (as metrofit-cli match --machine-def reads) or a project</source>
        <translation>Wczytaj plik JSON obrabiarki (tak jak czyta go metrofit-cli match --machine-def) lub projekt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E&amp;xport…</source>
        <translation>E&amp;ksportuj…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the machine JSON for metrofit-cli match --machine-def</source>
        <translation>Zapisz plik JSON obrabiarki dla metrofit-cli match --machine-def</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>B tilt axis (parallel to Y)</source>
        <translation>Oś uchylna B (równoległa do Y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A tilt axis (parallel to X)</source>
        <translation>Oś uchylna A (równoległa do X)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Travel of %1: the minimum %2° is above the maximum %3°.</source>
        <translation>Zakres ruchu %1: minimum %2° jest większe od maksimum %3°.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Travel of S%1: the minimum %2 mm is above the maximum %3 mm.</source>
        <translation>Zakres ruchu S%1: minimum %2 mm jest większe od maksimum %3 mm.</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 has no machine (studies.matching.machine).</source>
        <translation>%1 nie zawiera obrabiarki (studies.matching.machine).</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Import a machine</source>
        <translation>Importuj obrabiarkę</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Machine or project (*.json *.metrofit);;All files (*)</source>
        <translation>Obrabiarka lub projekt (*.json *.metrofit);;Wszystkie pliki (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export the machine</source>
        <translation>Eksportuj obrabiarkę</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Machine JSON (*.json)</source>
        <translation>JSON obrabiarki (*.json)</translation>
    </message>
</context>
<context>
    <name>metrofit::MainWindow</name>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="+60"/>
        <source>Metrofit projects (*.metrofit)</source>
        <translation>Projekty Metrofit (*.metrofit)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Autosave failed: %1</source>
        <translation>Automatyczny zapis nie powiódł się: %1</translation>
    </message>
    <message>
        <location line="+7"/>
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
        <source>&amp;Import data…</source>
        <translation>&amp;Importuj dane…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Adds a file (thermal log, probe points, CMM report, …) to the project as a dataset</source>
        <translation>Dodaje plik (rejestr termiczny, punkty pomiarowe, raport CMM, …) do projektu jako zbiór danych</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Recent files</source>
        <translation>Ostatnio &amp;używane</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+192"/>
        <source>&amp;Save</source>
        <translation>&amp;Zapisz</translation>
    </message>
    <message>
        <location line="-191"/>
        <source>Save &amp;As…</source>
        <translation>Zapisz &amp;jako…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export report PDF…</source>
        <translation>&amp;Eksportuj raport PDF…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Quit</source>
        <translation>Za&amp;kończ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Edit</source>
        <translation>&amp;Edycja</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <source>&amp;Undo</source>
        <translation>&amp;Cofnij</translation>
    </message>
    <message>
        <location line="-5"/>
        <location line="+8"/>
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
        <location line="+9"/>
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
        <source>&amp;Manual</source>
        <translation>&amp;Podręcznik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Shows the documentation: file formats, results, references</source>
        <translation>Pokazuje dokumentację: formaty plików, wyniki, źródła</translation>
    </message>
    <message>
        <location line="+4"/>
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
        <location line="+16"/>
        <source>%1[*] — Metrofit</source>
        <translation>%1[*] — Metrofit</translation>
    </message>
    <message>
        <location line="+34"/>
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
        <location line="+7"/>
        <source>Recovered the autosaved project; save it to keep it.</source>
        <translation>Przywrócono automatycznie zapisany projekt; zapisz go, aby go zachować.</translation>
    </message>
    <message>
        <location line="-48"/>
        <source>Cannot save the setup model</source>
        <translation>Nie można zapisać modelu ustawczego</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>The setup model (relation graph) has unsaved edits. Do you want to save them?</source>
        <translation>Model ustawczy (graf relacji) ma niezapisane zmiany. Czy chcesz je zapisać?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The project &quot;%1&quot; and the setup model (relation graph) have unsaved changes. Do you want to save them?</source>
        <translation>Projekt „%1” i model ustawczy (graf relacji) mają niezapisane zmiany. Czy chcesz je zapisać?</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Unsaved changes</source>
        <translation>Niezapisane zmiany</translation>
    </message>
    <message>
        <location line="+140"/>
        <location line="+5"/>
        <location line="+5"/>
        <source>Cannot show the manual</source>
        <translation>Nie można pokazać podręcznika</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>The documentation is not installed; looked for:
%1</source>
        <translation>Dokumentacja nie jest zainstalowana; szukano w:
%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot read %1</source>
        <translation>Nie można odczytać %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Import data</source>
        <translation>Import danych</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Cannot import the data</source>
        <translation>Nie można zaimportować danych</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Imported %1 as “%2”</source>
        <translation>Zaimportowano %1 jako „%2”</translation>
    </message>
    <message>
        <location line="-219"/>
        <source>The project &quot;%1&quot; has unsaved changes. Do you want to save them?</source>
        <translation>Projekt „%1” ma niezapisane zmiany. Czy chcesz je zapisać?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The project &quot;%1&quot; has unsaved changes, and the results of the last run are not saved either. Do you want to save them?</source>
        <translation>Projekt „%1” ma niezapisane zmiany, a wyniki ostatniego uruchomienia również nie są zapisane. Czy chcesz je zapisać?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The results of the last run are not saved in the project &quot;%1&quot; (they are lost when it is closed without saving). Do you want to save them?</source>
        <translation>Wyniki ostatniego uruchomienia nie są zapisane w projekcie „%1” (zostaną utracone, jeśli zostanie zamknięty bez zapisywania). Czy chcesz je zapisać?</translation>
    </message>
    <message>
        <location line="+19"/>
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
        <location line="+13"/>
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
        <location line="+21"/>
        <source>Cannot save the project</source>
        <translation>Nie można zapisać projektu</translation>
    </message>
    <message>
        <location line="-16"/>
        <location line="+22"/>
        <source>Saved %1</source>
        <translation>Zapisano %1</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Save project as</source>
        <translation>Zapisz projekt jako</translation>
    </message>
    <message>
        <location line="+23"/>
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
        <location line="+10"/>
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
    <name>metrofit::ManualWindow</name>
    <message>
        <location filename="../app/gui/manual.cpp" line="+39"/>
        <source>Metrofit manual</source>
        <translation>Podręcznik Metrofit</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&amp;Back</source>
        <translation>&amp;Wstecz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Contents</source>
        <translation>&amp;Spis treści</translation>
    </message>
</context>
<context>
    <name>metrofit::MatchingCurveView</name>
    <message>
        <location filename="../widgets/matching/matchingcurveview.cpp" line="+94"/>
        <source>generation</source>
        <translation>generacja</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>best RMS (mm)</source>
        <translation>RMS (mm)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Optimisation curve: run SADE or GA-simplex</source>
        <translation>Krzywa optymalizacji: uruchom SADE lub GA-simpleks</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Optimisation curve of the fine matching</source>
        <translation>Krzywa optymalizacji dopasowania dokładnego</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>least-squares optimum %1 mm</source>
        <translation>optimum najmniejszych kwadratów %1 mm</translation>
    </message>
</context>
<context>
    <name>metrofit::MatchingPage</name>
    <message>
        <location filename="../app/gui/matchingpage.cpp" line="+127"/>
        <source>SADE (rough + fine, paper settings)</source>
        <translation>SADE (zgrubne + dokładne, parametry z publikacji)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GA-simplex (rough + fine)</source>
        <translation>GA-simpleks (zgrubne + dokładne)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Closed form (least-squares optimum)</source>
        <translation>Postać zamknięta (optimum najmniejszych kwadratów)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Minimax (smallest largest deviation)</source>
        <translation>Minimaks (najmniejsza największa odchyłka)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>closed form</source>
        <translation>postać zamknięta</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>minimax</source>
        <translation>minimaks</translation>
    </message>
    <message>
        <location line="+201"/>
        <source>Allow &amp;scale</source>
        <translation>&amp;Skala</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Run</source>
        <translation>&amp;Uruchom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Save fr&amp;ame…</source>
        <translation>Z&amp;apisz frame…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mac&amp;hine…</source>
        <translation>O&amp;brabiarka…</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The posture shown after matching and used for the machine adjustment (every method is run for the comparison table)</source>
        <translation>Położenie pokazywane po dopasowaniu i używane do nastawienia maszyny (do tabeli porównawczej uruchamiana jest każda metoda)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Symmetric tolerance ±T of every point (mm)</source>
        <translation>Symetryczna tolerancja ±T każdego punktu (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit an isotropic scale too (e.g. thermal expansion of the part)</source>
        <translation>Dopasuj także skalę izotropową (np. rozszerzalność cieplna przedmiotu)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run every matching method on these points (Ctrl+R)</source>
        <translation>Uruchom każdą metodę dopasowania dla tych punktów (Ctrl+R)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the running SADE / GA-simplex search (Esc)</source>
        <translation>Zatrzymaj trwające przeszukiwanie SADE / GA-simpleks (Esc)</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Method</source>
        <translation>Metoda</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rx (deg)</source>
        <translation>rx (st.)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ry (deg)</source>
        <translation>ry (st.)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rz (deg)</source>
        <translation>rz (st.)</translation>
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
        <translation>skala</translation>
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
        <translation>maks. |d| (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out before</source>
        <translation>poza przed</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out after</source>
        <translation>poza po</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time (ms)</source>
        <translation>czas (ms)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Axis</source>
        <translation>Oś</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Wartość</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>Jednostka</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The machine the adjustment values are for: topology, geometry, travel and control (Ctrl+Shift+M)</source>
        <translation>Obrabiarka, dla której są wartości korekty: topologia, geometria, zakres ruchu i sterowanie (Ctrl+Shift+M)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Round</source>
        <translation>Runda</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max |d| measured (mm)</source>
        <translation>maks. |d| zmierzone (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out of tolerance</source>
        <translation>poza tolerancją</translation>
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
        <translation>rzeczywiste max |d| (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>true out of tolerance</source>
        <translation>rzeczywiście poza tolerancją</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SZ (mm)</source>
        <translation>SZ (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rotary 1 (deg)</source>
        <translation>oś obrotowa 1 (st.)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rotary 2 (deg)</source>
        <translation>oś obrotowa 2 (st.)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>frame rot. (deg)</source>
        <translation>obrót układu (st.)</translation>
    </message>
    <message>
        <location line="+11"/>
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
        <location line="+0"/>
        <source>Deviation after (mm)</source>
        <translation>Odchyłka po (mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Export deviations after matching (CSV)…</source>
        <translation>&amp;Eksportuj odchyłki po dopasowaniu (CSV)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Each point&apos;s signed deviation along its normal and its deviation vector after the fit: id, surface, d_mm, dx_mm, dy_mm, dz_mm</source>
        <translation>Odchyłka każdego punktu ze znakiem wzdłuż normalnej i jego wektor odchyłki po dopasowaniu: id, surface, d_mm, dx_mm, dy_mm, dz_mm</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The control the frame is written for: HEIDENHAIN datum shift and PLANE SPATIAL, SINUMERIK TRANS and AROT, FANUC G68.2</source>
        <translation>Sterowanie, dla którego zapisywany jest frame: HEIDENHAIN przesunięcie punktu zerowego i PLANE SPATIAL, SINUMERIK TRANS i AROT, FANUC G68.2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Decimals of the values in mm and ° (FANUC IS-B takes 3)</source>
        <translation>Miejsca po przecinku wartości w mm i ° (FANUC IS-B przyjmuje 3)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The blocks that set the frame; the saved program adds its frame and comments</source>
        <translation>Bloki ustawiające frame; zapisany program dodaje ramę programu i komentarze</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Controller frame</source>
        <translation>Frame sterowania</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Contro&amp;l:</source>
        <translation>Ste&amp;rowanie:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Decimals:</source>
        <translation>&amp;Miejsca po przecinku:</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Methods and &amp;machine</source>
        <translation>Metody i &amp;maszyna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Optimisation curve</source>
        <translation>Krzywa &amp;optymalizacji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;measure loop</source>
        <translation>Pętla ponownego pomia&amp;ru</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Points</source>
        <translation>Pu&amp;nkty</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Controller frame</source>
        <translation>&amp;Frame sterowania</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;Probe points:</source>
        <translation>&amp;Punkty sondowania:</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>M&amp;ethod:</source>
        <translation>M&amp;etoda:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Tolerance ±</source>
        <translation>&amp;Tolerancja ±</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Lock:</source>
        <translation>Zablokuj:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Hold %1 at 0 (a constrained optimum over the other parameters)</source>
        <translation>Utrzymaj %1 na 0 (optimum z ograniczeniem po pozostałych parametrach)</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Change the matching method</source>
        <translation>Zmiana metody dopasowania</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Change the matching tolerance</source>
        <translation>Zmiana tolerancji dopasowania</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Change the matching scale</source>
        <translation>Zmiana skali dopasowania</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Change the matching locks</source>
        <translation>Zmiana blokad dopasowania</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Change the control of the frame</source>
        <translation>Zmień sterowanie frame’u</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>Change the decimals of the frame</source>
        <translation>Zmień miejsca po przecinku frame’u</translation>
    </message>
    <message>
        <location line="+63"/>
        <location line="+314"/>
        <location line="+62"/>
        <source>Matching failed: %1</source>
        <translation>Dopasowanie nie powiodło się: %1</translation>
    </message>
    <message>
        <location line="+500"/>
        <source>No posture yet: press Run (Ctrl+R).</source>
        <translation>Brak położenia: naciśnij Uruchom (Ctrl+R).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>There is no posture to write yet: run the matching first (Ctrl+R)</source>
        <translation>Nie ma jeszcze położenia do zapisania: najpierw uruchom dopasowanie (Ctrl+R)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Datum shift (CYCL DEF 7) to the origin t, then PLANE SPATIAL with R = Rz(SPC) Ry(SPB) Rx(SPA) about the non-tilted axes; STAY: no axis moves. Call the saved program (CALL PGM) once the part&apos;s preset is active.</source>
        <translation>Przesunięcie punktu zerowego (CYCL DEF 7) do początku t, następnie PLANE SPATIAL z R = Rz(SPC) Ry(SPB) Rx(SPA) wokół nienachylonych osi; STAY: żadna oś się nie porusza. Wywołaj zapisany program (CALL PGM), gdy punkt bazowy detalu jest aktywny.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>TRANS to the origin t on top of the active settable frame (G54 …), then AROT about Z, Y&apos;, X&apos;&apos;: R = Rz(Z) Ry(Y) Rx(X). The tool is not oriented: use CYCLE800 or TRAORI for that.</source>
        <translation>TRANS do początku t na aktywny nastawny frame (G54 …), następnie AROT wokół Z, Y&apos;, X&apos;&apos;: R = Rz(Z) Ry(Y) Rx(X). Narzędzie nie jest orientowane: użyj do tego CYCLE800 lub TRAORI.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>G68.2 with the origin t and the Euler angles R = Rz(I) Rx(J) Rz(K), cancelled with G69. G53.1 is not written: it moves the rotary axes, program it at a safe position.</source>
        <translation>G68.2 z początkiem t i kątami Eulera R = Rz(I) Rx(J) Rz(K), odwoływane przez G69. G53.1 nie jest zapisywane: porusza osiami obrotowymi, zaprogramuj je w bezpiecznym położeniu.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Posture of %1 as a controller frame (mm, °).</source>
        <translation>Położenie z %1 jako frame sterowania (mm, °).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The fitted scale %1 is not applied: no control frame scales.</source>
        <translation>Dopasowana skala %1 nie jest stosowana: żaden frame sterowania nie skaluje.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Write the frame program for the control to a file (as metrofit-cli match --frame does)</source>
        <translation>Zapisz program frame’u dla sterowania do pliku (jak metrofit-cli match --frame)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot write the posture as a frame: %1</source>
        <translation>Nie można zapisać położenia jako frame: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>There is no posture to write yet: run the matching first.</source>
        <translation>Nie ma jeszcze położenia do zapisania: najpierw uruchom dopasowanie.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>There are no deviations after matching yet: run the matching first.</source>
        <translation>Nie ma jeszcze odchyłek po dopasowaniu: najpierw uruchom dopasowanie.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export the deviations after matching</source>
        <translation>Eksportuj odchyłki po dopasowaniu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv)</source>
        <translation>Pliki CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot export the deviations</source>
        <translation>Nie można wyeksportować odchyłek</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>HEIDENHAIN programs (*.h)</source>
        <translation>Programy HEIDENHAIN (*.h)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SINUMERIK subprograms (*.spf)</source>
        <translation>Podprogramy SINUMERIK (*.spf)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FANUC programs (*.nc)</source>
        <translation>Programy FANUC (*.nc)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save the controller frame</source>
        <translation>Zapisz frame sterowania</translation>
    </message>
    <message>
        <location line="-18"/>
        <location line="+19"/>
        <source>All files (*)</source>
        <translation>Wszystkie pliki (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot save the frame</source>
        <translation>Nie można zapisać frame’u</translation>
    </message>
    <message>
        <location line="-837"/>
        <source>The effects applied to the matching model are invalid:
%1</source>
        <translation>Efekty zastosowane do modelu dopasowania są nieprawidłowe:
%1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 points on %2 surfaces, %3%4.</source>
        <translation>Punkty: %1, powierzchnie: %2, %3%4.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Includes applied effects: %1 (the nominal points are deformed by them before matching).</source>
        <translation>Zawiera zastosowane efekty: %1 (punkty nominalne są przez nie odkształcane przed dopasowaniem).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Effects applied on the Diagnosis page belong to the probe points %1 (the ones the diagnosis ran on); these points use the declared model.</source>
        <translation>Efekty zastosowane na stronie Diagnoza należą do punktów sondowania %1 (tych, na których przeprowadzono diagnozę); te punkty używają zadeklarowanego modelu.</translation>
    </message>
    <message>
        <location line="-105"/>
        <location line="+208"/>
        <source>Settings changed: press Run (Ctrl+R) to match again.</source>
        <translation>Zmieniono ustawienia: naciśnij Uruchom (Ctrl+R), aby ponownie dopasować.</translation>
    </message>
    <message>
        <location line="-917"/>
        <source>studies.matching.tolerance_mm: %1 mm cannot be set on the page (it takes %2 to %3 mm in steps of %4 mm)</source>
        <translation>studies.matching.tolerance_mm: nie można ustawić %1 mm na stronie (przyjmuje od %2 do %3 mm w krokach co %4 mm)</translation>
    </message>
    <message>
        <location line="+761"/>
        <source>This project has no probe points. Import them with File › Import data… (Ctrl+I): probe points with their nominals, a hole table or a CMM report, or raw measured points whose nominals come from a fitted element or a second measurement.</source>
        <translation>Ten projekt nie ma punktów pomiarowych. Zaimportuj je przez Plik › Importuj dane… (Ctrl+I): punkty z ich wartościami nominalnymi, tabelę otworów lub raport CMM albo surowe punkty pomiarowe, których punkty nominalne pochodzą z dopasowanego elementu lub z drugiego pomiaru.</translation>
    </message>
    <message>
        <location line="+150"/>
        <source>The matching study&apos;s settings are invalid, nothing is run until they are corrected (Undo, or the project file): %1</source>
        <translation>Ustawienia badania dopasowania są nieprawidłowe; nic nie zostanie uruchomione, dopóki nie zostaną poprawione (Cofnij lub plik projektu): %1</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Lock %1 and run</source>
        <translation>Zablokuj %1 i uruchom</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The points cannot determine %1 (a sphere fixes no rotation, parallel normals fix no rotation about them): hold them at 0 and run again. Undo gives the locks back.</source>
        <translation>Punkty nie wyznaczają %1 (kula nie ustala żadnego obrotu, równoległe normalne nie ustalają obrotu wokół nich): utrzymaj je na 0 i uruchom ponownie. Cofnij przywraca blokady.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Lock %1</source>
        <translation>Zablokuj %1</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Matching …</source>
        <translation>Dopasowywanie …</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Match the probe points %1</source>
        <translation>Dopasuj punkty sondowania %1</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>The stored result (computed %1) is out of date: the matching settings changed since. Not matched with these settings yet: press Run (Ctrl+R).</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: ustawienia dopasowania zmieniły się od tego czasu. Jeszcze nie dopasowano z tymi ustawieniami: naciśnij Uruchom (Ctrl+R).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the points file changed since. Press Run (Ctrl+R) to match the points as they are now.</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: plik punktów zmienił się od tego czasu. Naciśnij Uruchom (Ctrl+R), aby dopasować punkty w obecnej postaci.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the points file cannot be read.</source>
        <translation>Nie można sprawdzić zapisanego wyniku (obliczonego %1): nie można odczytać pliku punktów.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>From the saved project, computed %1 with these settings on these points: %2: %3 of %4 points out of ±%5 mm before, %6 after; RMSE %7 mm, max |d| %8 mm. Press Run (Ctrl+R) to see the views.</source>
        <translation>Z zapisanego projektu, obliczono %1 z tymi ustawieniami dla tych punktów: %2: %3 z %4 punktów poza ±%5 mm przed, %6 po; RMSE %7 mm, maks. |d| %8 mm. Naciśnij Uruchom (Ctrl+R), aby zobaczyć widoki.</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>(The loop ran with the previous tolerance: Run again.)</source>
        <translation>(Pętla działała z poprzednią tolerancją: uruchom ponownie.)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 of %3 points out of ±%4 mm before, %5 after; RMSE %6 mm, max |d| %7 mm.%8</source>
        <translation>%1: %2 z %3 punktów poza ±%4 mm przed, %5 po; RMSE %6 mm, maks. |d| %7 mm.%8</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> Cancelled: the best posture found so far.</source>
        <translation> Anulowano: najlepsze dotąd znalezione położenie.</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>BEFORE matching
%1 of %2 out of ±%3 mm, max |d| %4 mm</source>
        <translation>PRZED dopasowaniem
%1 z %2 poza ±%3 mm, maks. |d| %4 mm</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>AFTER matching
not run yet: press Run (Ctrl+R)</source>
        <translation>PO dopasowaniu
jeszcze nie uruchomiono: naciśnij Uruchom (Ctrl+R)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>AFTER matching (%1)
%2 of %3 out of ±%4 mm, max |d| %5 mm</source>
        <translation>PO dopasowaniu (%1)
%2 z %3 poza ±%4 mm, maks. |d| %5 mm</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Shown after matching and used for the machine adjustment</source>
        <translation>Pokazywane po dopasowaniu i używane do nastawienia maszyny</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Rough</source>
        <translation>Zgrubne</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rough matching: 3-point local frames, Eq. 3–7</source>
        <translation>Dopasowanie zgrubne: lokalne układy 3-punktowe, równ. 3–7</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 is locked at %2: the rough stage&apos;s three-point frames cannot hold a lock, the fine stage (SADE) holds it.</source>
        <translation>%1 jest zablokowany na %2: trzypunktowe układy etapu zgrubnego nie mogą utrzymać blokady, utrzymuje ją etap dokładny (SADE).</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>head-head, Eq. 12–13</source>
        <translation>głowica-głowica, równ. 12–13</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>table-table trunnion</source>
        <translation>stół-stół, kołyska</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B swivel head, C rotary table</source>
        <translation>głowica uchylna B, stół obrotowy C</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the project&apos;s machine %1 (%2)</source>
        <translation>obrabiarka projektu %1 (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the default machine %1 (%2): no machine is defined for this project; enter yours with Machine… (Ctrl+Shift+M) before using these values at the control</source>
        <translation>domyślna obrabiarka %1 (%2): dla tego projektu nie zdefiniowano obrabiarki; wprowadź swoją przez Obrabiarka… (Ctrl+Shift+M), zanim użyjesz tych wartości na sterowaniu</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Adjustment values will be for %1.</source>
        <translation>Wartości korekty będą dla: %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Machine adjustment values for %1, posture of %2. %3</source>
        <translation>Korekty obrabiarki: %1, położenie z %2. %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Within travel.</source>
        <translation>W zakresie przesuwu.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OUTSIDE TRAVEL: %1</source>
        <translation>POZA ZAKRESEM PRZESUWU: %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+2"/>
        <source>Change the machine</source>
        <translation>Zmień obrabiarkę</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Change the controller frame</source>
        <translation>Zmień frame sterowania</translation>
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
        <translation>st.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>frame rotation</source>
        <translation>obrót układu współrzędnych</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The remeasure loop did not run.</source>
        <translation>Pętla ponownego pomiaru nie została uruchomiona.</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+2"/>
        <source>S%1 (deg)</source>
        <translation>S%1 (st.)</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>Every point is inside the tolerance after %n adjustment(s); the true remaining error is %1 mm at most.</source>
        <translation>
            <numerusform>Po %n korekcie każdy punkt mieści się w tolerancji; rzeczywisty błąd resztkowy wynosi najwyżej %1 mm.</numerusform>
            <numerusform>Po %n korektach każdy punkt mieści się w tolerancji; rzeczywisty błąd resztkowy wynosi najwyżej %1 mm.</numerusform>
            <numerusform>Po %n korektach każdy punkt mieści się w tolerancji; rzeczywisty błąd resztkowy wynosi najwyżej %1 mm.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>FAILED: the best fit leaves points out of tolerance (form error larger than the tolerance); no WCS adjustment can bring them in. True remaining error %1 mm, %2 point(s) out.</source>
        <translation>NIEPOWODZENIE: najlepsze dopasowanie pozostawia punkty poza tolerancją (błąd kształtu większy niż tolerancja); żadna korekta układu przedmiotu nie może ich do niej wprowadzić. Rzeczywisty błąd resztkowy %1 mm, punktów poza tolerancją: %2.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>FAILED: the adjustment is beyond the machine&apos;s travel (%1); the WCS was not moved. True remaining error %2 mm.</source>
        <translation>NIEPOWODZENIE: korekta wykracza poza zakres ruchu obrabiarki (%1); układ przedmiotu nie został przesunięty. Rzeczywisty błąd resztkowy %2 mm.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>FAILED: still out of tolerance after the last adjustment. True remaining error %1 mm.</source>
        <translation>NIEPOWODZENIE: po ostatniej korekcie nadal poza tolerancją. Rzeczywisty błąd resztkowy %1 mm.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stopped before the end.</source>
        <translation>Zatrzymano przed końcem.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Step 7 with the simulator as machine and CMM (the part where the probe found it, with its form error; the %1 fit does not place it; probing noise %2 mm): measure, match, adjust the WCS, remeasure. %3</source>
        <translation>Krok 7 z symulatorem jako obrabiarką i WMP (przedmiot tam, gdzie znalazła go sonda, z jego błędem kształtu; dopasowanie %1 go nie umieszcza; szum pomiaru %2 mm): pomiar, dopasowanie, korekta układu przedmiotu, ponowny pomiar. %3</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>stopped: %1</source>
        <translation>zatrzymano: %1</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>in tolerance: no adjustment</source>
        <translation>w tolerancji: bez korekty</translation>
    </message>
    <message>
        <location line="-654"/>
        <source>with normals</source>
        <translation>z normalnymi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>positions only</source>
        <translation>tylko położenia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, planar</source>
        <translation>, płaskie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Licence: %1.</source>
        <translation>Licencja: %1.</translation>
    </message>
    <message>
        <location line="-94"/>
        <location line="+111"/>
        <location line="+55"/>
        <source>Not matched yet: press Run (Ctrl+R).</source>
        <translation>Jeszcze nie dopasowano: naciśnij Uruchom (Ctrl+R).</translation>
    </message>
    <message>
        <location line="-45"/>
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
        <location filename="../app/gui/overviewpage.cpp" line="+31"/>
        <source>Project overview</source>
        <translation>Przegląd projektu</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+110"/>
        <source>Project name</source>
        <translation>Nazwa projektu</translation>
    </message>
    <message>
        <location line="-108"/>
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
        <location line="+12"/>
        <source>&lt;b&gt;New here?&lt;/b&gt; Open the demo project: sample data for every study (setup correction, posture matching, kinematics &amp;amp; SPC, thermal, diagnosis) to try each page. It is also in &lt;i&gt;Help › Open demo project&lt;/i&gt;.</source>
        <translation>&lt;b&gt;Pierwszy raz?&lt;/b&gt; Otwórz projekt demonstracyjny: przykładowe dane dla każdego studium (korekcja danych ustawczych, dopasowanie położenia, kinematyka i SPC, termika, diagnoza), aby wypróbować każdą stronę. Jest też dostępny w menu &lt;i&gt;Pomoc › Otwórz projekt demonstracyjny&lt;/i&gt;.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Open the demo project</source>
        <translation>&amp;Otwórz projekt demonstracyjny</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Copies the bundled demo project into a folder of your own and opens it</source>
        <translation>Kopiuje dołączony projekt demonstracyjny do własnego folderu i otwiera go</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Hide this hint (it does not come back)</source>
        <translation>Ukryj tę wskazówkę (nie pojawi się ponownie)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>&amp;Import data…</source>
        <translation>&amp;Importuj dane…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Adds a file to the project as a dataset (File › Import data…, Ctrl+I, or drop files on the window); right-click a dataset to rename, re-link or remove it</source>
        <translation>Dodaje plik do projektu jako zbiór danych (Plik › Importuj dane…, Ctrl+I lub przeciągnij pliki na okno); prawy przycisk myszy na zbiorze danych: zmiana nazwy, ponowne połączenie lub usunięcie</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>not saved yet</source>
        <translation>jeszcze nie zapisano</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Study settings the methods cannot use; correct them in the project file:</source>
        <translation>Ustawienia badań, których metody nie mogą użyć; popraw je w pliku projektu:</translation>
    </message>
</context>
<context>
    <name>metrofit::PointSetView</name>
    <message>
        <location filename="../widgets/matching/pointsetview.cpp" line="+362"/>
        <source>deviation
(mm)</source>
        <translation>odchyłka
(mm)</translation>
    </message>
    <message>
        <location line="+231"/>
        <source>grey: nominal points; coloured: measured, deviation vectors x%1</source>
        <translation>szare: nominalne; kolorowe: zmierzone, wektory odchyłek x%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>after matching: solid; before (nominal and measured): faded</source>
        <translation>po dopasowaniu: pełne; przed (nominalne i zmierzone): wyblakłe</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the part: coloured as the nearest probed point, light grey where none is near</source>
        <translation>część: kolor najbliższego punktu pomiarowego, jasnoszara tam, gdzie żadnego nie ma w pobliżu</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>green: within ±%1 mm; large: out of tolerance</source>
        <translation>zielone: w granicach ±%1 mm; duże: poza tolerancją</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>3D view needs an X11 display (run under xvfb-run for headless use)</source>
        <translation>Widok 3D wymaga ekranu X11 (bez monitora uruchom przez xvfb-run)</translation>
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
kąt: %2°
odchyłka: %3 µm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CCW</source>
        <translation>CCW</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CW</source>
        <translation>CW</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>expected after compensation</source>
        <translation>oczekiwane po kompensacji</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Radial deviation of the measured path from the nominal circle, magnified (ballbar plot): plotted radius = R + k × deviation. Blue: CCW loop, orange: CW loop; the rings are labelled in µm.</source>
        <translation>Odchyłka promieniowa zmierzonego toru od okręgu nominalnego, powiększona (wykres ballbar): promień na wykresie = R + k × odchyłka. Niebieski: pętla przeciwnie do ruchu wskazówek zegara, pomarańczowy: zgodnie; okręgi opisano w µm.</translation>
    </message>
</context>
<context>
    <name>metrofit::PreferencesDialog</name>
    <message>
        <location filename="../app/gui/preferencesdialog.cpp" line="+19"/>
        <source>Preferences</source>
        <translation>Preferencje</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System</source>
        <translation>Systemowy</translation>
    </message>
    <message>
        <location line="+8"/>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation>Wył.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>While the project has unsaved changes, a copy is written next to it this often, and offered for recovery after a crash (0: off)</source>
        <translation>Dopóki projekt ma niezapisane zmiany, w tych odstępach obok niego zapisywana jest kopia, proponowana do przywrócenia po awarii (0: wyłączone)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The language is applied at the next start of Metrofit.</source>
        <translation>Język zostanie zastosowany przy następnym uruchomieniu programu Metrofit.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Language:</source>
        <translation>&amp;Język:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Autosave every:</source>
        <translation>&amp;Autozapis co:</translation>
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
        <location filename="../widgets/document/projectdocument.cpp" line="+35"/>
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
        <location line="+200"/>
        <source>Untitled</source>
        <translation>Bez nazwy</translation>
    </message>
    <message>
        <location line="+160"/>
        <source>the project has not been saved yet; choose a file name with Save As</source>
        <translation>projekt nie został jeszcze zapisany; wybierz nazwę pliku poleceniem „Zapisz jako”</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>the project has no dataset &apos;%1&apos;</source>
        <translation>projekt nie ma zbioru danych „%1”</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+26"/>
        <source>a dataset needs an id</source>
        <translation>zbiór danych wymaga identyfikatora</translation>
    </message>
    <message>
        <location line="-23"/>
        <location line="+26"/>
        <source>the project already has a dataset &apos;%1&apos;</source>
        <translation>projekt ma już zbiór danych „%1”</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>Import dataset %1</source>
        <translation>Import zbioru danych %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Remove dataset %1</source>
        <translation>Usunięcie zbioru danych %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Rename dataset %1 to %2</source>
        <translation>Zmiana nazwy zbioru danych %1 na %2</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Re-link dataset %1</source>
        <translation>Ponowne połączenie zbioru danych %1</translation>
    </message>
</context>
<context>
    <name>metrofit::ProjectNavigator</name>
    <message>
        <location filename="../app/gui/projectnavigator.cpp" line="+91"/>
        <source>Add report features to setup model…</source>
        <translation>Dodaj elementy raportu do modelu ustawienia…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Create setup model from report…</source>
        <translation>Utwórz model ustawienia z raportu…</translation>
    </message>
    <message>
        <location line="+34"/>
        <location line="+39"/>
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
    <name>metrofit::Report</name>
    <message>
        <location filename="../widgets/report/diagnosissection.cpp" line="+42"/>
        <location filename="../widgets/report/thermalsection.cpp" line="+743"/>
        <source>Thermal</source>
        <translation>Termika</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kinematic</source>
        <translation>Kinematyka</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setup data</source>
        <translation>Dane ustawcze</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Posture matching</source>
        <translation>Dopasowanie położenia</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>form %1</source>
        <translation>postać %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>rmse %1 %2, max |e| %3 %2</source>
        <translation>rmse %1 %2, maks. |e| %3 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, held-out rmse %1 %2</source>
        <translation>, rmse danych testowych %1 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>rmse %1 %2</source>
        <translation>RMSE %1 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, held-out %1 %2</source>
        <translation>, odłożone %1 %2</translation>
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
        <translation>Nie można było przeprowadzić diagnozy: %1</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+113"/>
        <source>Closed loop: %1</source>
        <translation>Zamknięta pętla: %1</translation>
    </message>
    <message>
        <location line="-111"/>
        <location line="+133"/>
        <source>not checked</source>
        <translation>nie sprawdzono</translation>
    </message>
    <message>
        <location line="-132"/>
        <source>Correct the diagnosis settings of this study.</source>
        <translation>Popraw ustawienia diagnozy tego badania.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Declared model: %1 a static linear function of %2, fitted on the first %3 % of the rows and held out on the rest.</source>
        <translation>Zadeklarowany model: %1 jako statyczna funkcja liniowa %2, dopasowana na pierwszych %3 % wierszy, reszta to dane testowe.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Declared model: the Cartesian machine&apos;s actuator errors (origin, axis angles).</source>
        <translation>Zadeklarowany model: błędy napędów maszyny kartezjańskiej (początek, kąty osi).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Declared model: constant setup-data errors acting through the relation graph of %1.</source>
        <translation>Zadeklarowany model: stałe błędy danych ustawczych działające przez graf relacji %1.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Declared model: a rigid posture error (rotation and translation); tolerance ±%1 mm.</source>
        <translation>Zadeklarowany model: sztywny błąd położenia (obrót i przesunięcie); tolerancja ±%1 mm.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Step 0, the declared model: %1.</source>
        <translation>Krok 0, zadeklarowany model: %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>effect</source>
        <translation>efekt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>parameters ± standard error</source>
        <translation>parametry ± błąd standardowy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rmse (%1)</source>
        <translation>rmse (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>held-out (%1)</source>
        <translation>dane testowe (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accepted</source>
        <translation>przyjęty</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../widgets/report/kinematicsection.cpp" line="+119"/>
        <location line="+138"/>
        <location filename="../widgets/report/thermalsection.cpp" line="-418"/>
        <source>yes</source>
        <translation>tak</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../widgets/report/kinematicsection.cpp" line="-138"/>
        <location line="+138"/>
        <source>no</source>
        <translation>nie</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Evidence, per candidate (# = loop round):</source>
        <translation>Dowody dla każdego kandydata (# = runda pętli):</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No candidate passed the evidence test: the declared model is kept. %1.</source>
        <translation>Żaden kandydat nie przeszedł testu dowodów: zadeklarowany model zostaje zachowany. %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Accepted: %1. Final model: %2.</source>
        <translation>Przyjęto: %1. Model końcowy: %2.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Residual before and after %1</source>
        <translation>Residua przed i po %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../widgets/report/thermalsection.cpp" line="+253"/>
        <source>error (%1)</source>
        <translation>błąd (%1)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>declared model</source>
        <translation>zadeklarowany model</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>with accepted effects</source>
        <translation>z przyjętymi efektami</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rmse (fitted data)</source>
        <translation>rmse (dane dopasowania)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max |e| (fitted data)</source>
        <translation>maks. |e| (dane dopasowania)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>rmse (held-out rows)</source>
        <translation>rmse (wiersze testowe)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: no effect beyond the declared model is supported by the data.</source>
        <translation>%1: dane nie potwierdzają żadnego efektu poza zadeklarowanym modelem.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the declared model lacks %2.</source>
        <translation>%1: zadeklarowanemu modelowi brakuje %2.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Still unexplained: %1</source>
        <translation>Wciąż niewyjaśnione: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add %1 to the model (Apply on the Diagnosis page).</source>
        <translation>Dodaj %1 do modelu (Zastosuj na stronie Diagnoza).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add %1 to the model (Apply on the Diagnosis page), then look for the cause of what is still unexplained before trusting the compensation further.</source>
        <translation>Dodaj %1 do modelu (Zastosuj na stronie Diagnoza), a następnie znajdź przyczynę tego, co wciąż niewyjaśnione, zanim zaufasz kompensacji.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Keep the declared model: its residual is noise.</source>
        <translation>Zachowaj zadeklarowany model: jego residuum to szum.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the declared model, and look for the cause of what is still unexplained (a variable not recorded, a change in the process).</source>
        <translation>Zachowaj zadeklarowany model i znajdź przyczynę tego, co wciąż niewyjaśnione (niezarejestrowana zmienna, zmiana w procesie).</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Final residual against %1</source>
        <translation>Końcowe residuum względem %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Final residual against %1 with the generic fit (%2)</source>
        <translation>Końcowe residuum względem %1 z dopasowaniem ogólnym (%2)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Closed loop: diagnosis</source>
        <translation>Pętla zamknięta: diagnoza</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>For each study the declared model is fitted and its residual computed; candidate effects the model lacks are tried one by one, each estimated with its parameters and their standard errors. An effect is accepted only on evidence (out-of-sample improvement for thermal, an information criterion with a conservative threshold elsewhere) and when it reduces the error by a practically relevant amount; the model is refitted with it and the search repeated until nothing more is found.</source>
        <translation>Dla każdego studium dopasowywany jest zadeklarowany model i obliczane jego residuum; brakujące w modelu efekty kandydujące są sprawdzane kolejno, każdy estymowany wraz z parametrami i ich błędami standardowymi. Efekt jest przyjmowany tylko na podstawie dowodów (poprawa na danych testowych dla termiki, w pozostałych przypadkach kryterium informacyjne z ostrożnym progiem) i gdy zmniejsza błąd o praktycznie istotną wartość; model jest ponownie dopasowywany z tym efektem, a wyszukiwanie powtarzane, dopóki nic więcej nie zostanie znalezione.</translation>
    </message>
    <message>
        <location filename="../widgets/report/kinematicsection.cpp" line="-214"/>
        <location line="+267"/>
        <source>error</source>
        <translation>błąd</translation>
    </message>
    <message>
        <location line="-267"/>
        <source>identified</source>
        <translation>zidentyfikowany</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>standard error</source>
        <translation>błąd standardowy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulated (true)</source>
        <translation>symulowany (rzeczywisty)</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+270"/>
        <source>origin x (µm)</source>
        <translation>początek x (µm)</translation>
    </message>
    <message>
        <location line="-268"/>
        <location line="+270"/>
        <source>origin y (µm)</source>
        <translation>początek y (µm)</translation>
    </message>
    <message>
        <location line="-268"/>
        <location line="+269"/>
        <source>X axis angle a (deg)</source>
        <translation>kąt osi X a (stopnie)</translation>
    </message>
    <message>
        <location line="-267"/>
        <location line="+269"/>
        <source>Y axis angle b (deg)</source>
        <translation>kąt osi Y b (stopnie)</translation>
    </message>
    <message>
        <location line="-267"/>
        <location line="+269"/>
        <source>squareness b − a (deg)</source>
        <translation>prostopadłość b − a (stopnie)</translation>
    </message>
    <message>
        <location line="-267"/>
        <source>RMS residual (µm)</source>
        <translation>residuum RMS (µm)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>ISO 230-4 results</source>
        <translation>Wyniki według ISO 230-4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Per direction: the circular deviation G (radial range about the path&apos;s own least-squares centre) and the radial deviation F (largest and smallest deviation from the nominal radius about the nominal centre).</source>
        <translation>Dla każdego kierunku: odchyłka kołowości G (rozstęp promieni wokół środka okręgu średniokwadratowego danej ścieżki) i odchyłka promieniowa F (największa i najmniejsza odchyłka od promienia nominalnego wokół środka nominalnego).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>direction</source>
        <translation>kierunek</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>G (µm)</source>
        <translation>G (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>F max (µm)</source>
        <translation>F maks. (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>F min (µm)</source>
        <translation>F min. (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>LSQ centre (mm)</source>
        <translation>środek okręgu LSQ (mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CCW</source>
        <translation>CCW</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CW</source>
        <translation>CW</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Circular hysteresis H (largest radial difference between the CW and the CCW path at the same angle, about one least-squares centre): %1 µm.</source>
        <translation>Histereza kołowa H (największa różnica promieniowa między ścieżką CW i CCW przy tym samym kącie, wokół jednego wspólnego środka okręgu średniokwadratowego): %1 µm.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Circular hysteresis H: not available (the test has one direction only).</source>
        <translation>Histereza kołowa H: niedostępna (test ma tylko jeden kierunek).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ballbar breakdown</source>
        <translation>Rozkład ballbar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not available: %1.</source>
        <translation>Niedostępny: %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The radial deviation of %1 fitted by least squares to the signature of each cause, after the centre and radius of each run; ranked by share, the part of the radial deviation&apos;s variance the cause explains. A cause is above the noise when its value exceeds three standard errors.</source>
        <translation>Odchylenie promieniowe %1 dopasowane metodą najmniejszych kwadratów do sygnatury każdej przyczyny, po środku i promieniu każdego przebiegu; uporządkowane według udziału, czyli części wariancji odchylenia promieniowego, którą wyjaśnia przyczyna. Przyczyna jest ponad szumem, gdy jej wartość przekracza trzy błędy standardowe.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>both runs (CCW and CW)</source>
        <translation>obu przebiegów (CCW i CW)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the one run (without the reversal causes, which need both directions)</source>
        <translation>jedynego przebiegu (bez przyczyn nawrotnych, które wymagają obu kierunków)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cause</source>
        <translation>przyczyna</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>value (µm)</source>
        <translation>wartość (µm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>± std. error (µm)</source>
        <translation>± błąd standardowy (µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>share (%)</source>
        <translation>udział (%)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>above the noise</source>
        <translation>ponad szumem</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+313"/>
        <source>Circular test “%1”</source>
        <translation>Test kołowy „%1”</translation>
    </message>
    <message>
        <location line="-305"/>
        <source>%1 points; nominal circle R %2 mm about (%3, %4) mm; %5 loops (CCW, then CW). The actuator errors of the Cartesian machine (%8, Eq. 9: P = o + ir·x + jr·y, ir = (cos a, sin a), jr = (−sin b, cos b)) were identified by Levenberg-Marquardt (%6, iterations: %7); standard errors from the residuals.</source>
        <translation>%1 punktów; okrąg nominalny R %2 mm wokół (%3; %4) mm; %5 pętli (przeciwnie, potem zgodnie z ruchem wskazówek zegara). Błędy napędów maszyny kartezjańskiej (%8, równ. 9: P = o + ir·x + jr·y, ir = (cos a, sin a), jr = (−sin b, cos b)) wyznaczono metodą Levenberga-Marquardta (%6, iteracje: %7); błędy standardowe z residuów.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Includes applied effects: %1 (added with Apply on the diagnosis page). The errors above were identified with them and the compensated references include their corrections.</source>
        <translation>Zawiera zastosowane efekty: %1 (dodane przyciskiem „Zastosuj do modelu” na stronie diagnozy). Powyższe błędy zidentyfikowano z ich uwzględnieniem, a skompensowane wartości zadane zawierają ich korekcje.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>RMS residual of the declared model alone: %1 µm.</source>
        <translation>Residuum RMS samego zadeklarowanego modelu: %1 µm.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Path (XY)</source>
        <translation>Tor (XY)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+288"/>
        <source>Radial deviation (polar, magnified)</source>
        <translation>Odchyłka promieniowa (biegunowo, powiększona)</translation>
    </message>
    <message>
        <location line="-272"/>
        <source>Compensation</source>
        <translation>Kompensacja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compensated references for the nominal circle (the commanded points of the test) from the identified errors (Eq. 15), and the largest |radial deviation| from the nominal circle before and after:</source>
        <translation>Skompensowane wartości zadane dla okręgu nominalnego (zadane punkty testu) na podstawie zidentyfikowanych błędów (równ. 15) oraz największa |odchyłka promieniowa| od okręgu nominalnego przed i po:</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>path</source>
        <translation>tor</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max. dev. (µm)</source>
        <translation>maks. odch. (µm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>measured, before compensation</source>
        <translation>zmierzony, przed kompensacją</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>after, through the simulated machine (true errors, noise free)</source>
        <translation>po, przez maszynę symulowaną (rzeczywiste błędy, bez szumu)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>after, expected from the measured residual (noise stays)</source>
        <translation>po, oczekiwany z zmierzonego residuum (szum pozostaje)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>after, through the identified model</source>
        <translation>po, przez zidentyfikowany model</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest correction |reference − nominal|</source>
        <translation>największa korekcja |wartość zadana − nominalna|</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Statistical process control</source>
        <translation>Statystyczne sterowanie procesem</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+291"/>
        <source>The SPC series could not be charted: %1</source>
        <translation>Nie można było wykreślić serii SPC: %1</translation>
    </message>
    <message>
        <location line="-282"/>
        <source>Statistical process control of “%1” (%2)</source>
        <translation>Statystyczne sterowanie procesem: „%1” (%2)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Histogram of %1 (%2 values)</source>
        <translation>Histogram %1 (wartości: %2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>index</source>
        <translation>indeks</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../widgets/report/matchingsection.cpp" line="+437"/>
        <location filename="../widgets/report/summarysection.cpp" line="+157"/>
        <source>value</source>
        <translation>wartość</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>subgroups × size</source>
        <translation>podgrupy × liczność</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A2 / D3 / D4</source>
        <translation>A2 / D3 / D4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>X-bar chart CL / UCL / LCL</source>
        <translation>karta X-średnie CL / UCL / LCL</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>R chart CL / UCL / LCL</source>
        <translation>karta R CL / UCL / LCL</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+151"/>
        <location line="+99"/>
        <source>in control</source>
        <translation>pod kontrolą</translation>
    </message>
    <message>
        <location line="-249"/>
        <source>Nelson rules (subgroups)</source>
        <translation>Reguły Nelsona (podgrupy)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>σ within (R̄ / d2)</source>
        <translation>σ wewnątrz (R̄ / d2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>LSL / USL</source>
        <translation>LSL / USL</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cp (Eq. 16) / Cpk</source>
        <translation>Cp (równ. 16) / Cpk</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>natural tolerance (Eq. 17)</source>
        <translation>tolerancja naturalna (równ. 17)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>systematic error (Eq. 20)</source>
        <translation>błąd systematyczny (równ. 20)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1%2 ± %3 (%4)</source>
        <translation>%1%2 ± %3 (%4)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>significant</source>
        <translation>istotny</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not significant</source>
        <translation>nieistotny</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>regression offset angle (Fig. 10)</source>
        <translation>kąt przesunięcia regresji (rys. 10)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1° (slope %2%3 per sample, r² %4)</source>
        <translation>%1° (nachylenie %2%3 na próbkę, r² %4)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+128"/>
        <location line="+97"/>
        <source>SPC-gated compensation: %1</source>
        <translation>Kompensacja warunkowana SPC: %1</translation>
    </message>
    <message>
        <location line="-218"/>
        <source>From the SPC offset angle to actuator errors</source>
        <translation>Od kąta przesunięcia SPC do błędów napędów</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The actuator errors could not be derived from the edges: %1</source>
        <translation>Nie udało się wyznaczyć błędów napędów z krawędzi: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The regression line of the deviation of an edge machined along X against the measured position (%1, Fig. 10, Table 2) has the offset angle atan(slope); by Eq. 9 it is the X actuator&apos;s orientation error a, minus the offset angle of the edge along Y is b, and the two intercepts give the actuator origin (Table 3). A slope or intercept within ± %2 standard errors counts as scatter. The circular test&apos;s identification is an independent estimate of the same errors.</source>
        <translation>Prosta regresji odchyłki krawędzi obrobionej wzdłuż X względem zmierzonego położenia (%1, rys. 10, tab. 2) ma kąt przesunięcia atan(nachylenia); wg równ. 9 jest to błąd orientacji a napędu X, ujemny kąt krawędzi wzdłuż Y to b, a oba wyrazy wolne dają początek napędów (tab. 3). Nachylenie lub wyraz wolny w granicach ± %2 błędów standardowych uznaje się za rozrzut. Identyfikacja z testu kołowego jest niezależną estymacją tych samych błędów.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>from SPC</source>
        <translation>z SPC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>from circular test</source>
        <translation>z testu kołowego</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>offset angle, edge along X (deg)</source>
        <translation>kąt przesunięcia, krawędź wzdłuż X (stopnie)</translation>
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
        <translation>kąt przesunięcia, krawędź wzdłuż Y (stopnie)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>systematic error, edge along X / Y (Eq. 20, µm)</source>
        <translation>błąd systematyczny, krawędź wzdłuż X / Y (równ. 20, µm)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Compensation applied (Eq. 15): the largest correction of the nominal circle is %1 µm; the circular test&apos;s model gives a largest deviation of %2 µm before and %3 µm with the references derived from SPC.</source>
        <translation>Kompensacja zastosowana (równ. 15): największa korekta okręgu nominalnego wynosi %1 µm; model testu kołowego daje największą odchyłkę %2 µm przed i %3 µm z wartościami zadanymi wyznaczonymi z SPC.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not compensated: %1</source>
        <translation>Bez kompensacji: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Three axes: circular tests in XY, YZ and ZX</source>
        <translation>Trzy osie: testy kołowe w XY, YZ i ZX</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The three-axis errors could not be identified: %1</source>
        <translation>Nie udało się zidentyfikować błędów trzech osi: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The three-axis Cartesian model P = o + [i j k]·Pr (%1, Eq. 9 in three axes) fitted to the three tests together (%2 points, RMS residual %3 µm): origin (%4, %5, %6) µm. In every plane (u, v) the u actuator moves along (cos a, sin a), the v actuator along (−sin b, cos b); squareness b − a.</source>
        <translation>Trzyosiowy model kartezjański P = o + [i j k]·Pr (%1, równ. 9 dla trzech osi) dopasowany łącznie do trzech testów (punkty: %2, residuum RMS %3 µm): początek (%4; %5; %6) µm. W każdej płaszczyźnie (u, v) napęd u porusza się wzdłuż (cos a, sin a), napęd v wzdłuż (−sin b, cos b); prostopadłość b − a.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>plane</source>
        <translation>płaszczyzna</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>a (deg)</source>
        <translation>a (stopnie)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>b (deg)</source>
        <translation>b (stopnie)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>squareness (deg)</source>
        <translation>prostopadłość (stopnie)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMS (µm)</source>
        <translation>RMS (µm)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Circular test %1: actuator origin offset (%2, %3) µm, squareness error %4°; largest radial deviation %5 µm.</source>
        <translation>Test okrągłości %1: przesunięcie początku napędów (%2; %3) µm, błąd prostopadłości %4°; największe odchylenie promieniowe %5 µm.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>compensated references (G-code)</source>
        <translation>skompensowane wartości zadane (G-code)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up to %1 µm</source>
        <translation>do %1 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>file %1 (Kinematics page, Export G-code)</source>
        <translation>plik %1 (strona Kinematyka, Eksport G-code)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>largest radial deviation %1 µm</source>
        <translation>największe odchylenie promieniowe %1 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 µm expected with the compensated references</source>
        <translation>%1 µm oczekiwane ze skompensowanymi wartościami zadanymi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The identified actuator errors explain the measured path; with the compensated references the largest radial deviation falls from %1 µm to about %2 µm (the measuring noise stays).</source>
        <translation>Wyznaczone błędy napędów wyjaśniają zmierzoną ścieżkę; ze skompensowanymi wartościami zadanymi największe odchylenie promieniowe spada z %1 µm do około %2 µm (szum pomiarowy pozostaje).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Run the compensated references (%1) and repeat the circular test.</source>
        <translation>Uruchom skompensowane wartości zadane (%1) i powtórz test okrągłości.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Do not compensate: the references would not reduce the deviation.</source>
        <translation>Nie kompensuj: wartości zadane nie zmniejszyłyby odchylenia.</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+99"/>
        <source>SPC of %1: %2.</source>
        <translation>SPC dla %1: %2.</translation>
    </message>
    <message>
        <location line="-96"/>
        <location line="+98"/>
        <source>out of control</source>
        <translation>poza kontrolą</translation>
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
        <translation>Z kątów przesunięcia SPC: początek (%1; %2) µm, prostopadłość %3°.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Squareness XY %1°, YZ %2°, ZX %3° (three-plane circular tests).</source>
        <translation>Prostopadłość XY %1°, YZ %2°, ZX %3° (testy kołowe w trzech płaszczyznach).</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 points of a radial-only circular test (angle and radial deviation, as ballbar software exports it); %2 loops. It has no commanded and measured x/y coordinates, so the actuator errors cannot be identified from it and no compensation is computed; its ISO 230-4 results follow.</source>
        <translation>%1 punktów testu okrągłości tylko z odchyłkami promieniowymi (kąt i odchyłka promieniowa, tak jak eksportuje je oprogramowanie ballbar); pętle: %2. Test nie ma zadanych i zmierzonych współrzędnych x/y, więc nie można z niego zidentyfikować błędów napędów i nie oblicza się kompensacji; poniżej jego wyniki według ISO 230-4.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Circular test %1 (radial only): largest circular deviation G %2 µm.</source>
        <translation>Test okrągłości %1 (tylko promieniowy): największa odchyłka kołowości G %2 µm.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Circular hysteresis H %1 µm.</source>
        <translation>Histereza kołowa H %1 µm.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The test gives the ISO 230-4 results only: a radial-only test cannot identify the actuator errors.</source>
        <translation>Test daje tylko wyniki według ISO 230-4: test wyłącznie promieniowy nie pozwala zidentyfikować błędów napędów.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>To identify and compensate the actuator errors, record the circular test with commanded and measured x/y coordinates.</source>
        <translation>Aby zidentyfikować i skompensować błędy napędów, zarejestruj test okrągłości z zadanymi i zmierzonymi współrzędnymi x/y.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The project has no circular test: the study charts its part series only; no actuator errors are identified and no compensation is computed.</source>
        <translation>Projekt nie ma testu kołowego: badanie pokazuje tylko serię części; błędy napędów nie są identyfikowane, a kompensacja nie jest obliczana.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No SPC series is chosen.</source>
        <translation>Nie wybrano serii SPC.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Choose the series and its column on the Kinematics page, SPC tab.</source>
        <translation>Wybierz serię i jej kolumnę na stronie Kinematyka, karta SPC.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Keep charting the series; act when a point leaves the limits.</source>
        <translation>Prowadź dalej kartę serii; reaguj, gdy punkt wyjdzie poza granice.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Find the assignable cause of the out-of-control points before compensating.</source>
        <translation>Przed kompensacją znajdź przyczynę specjalną punktów poza granicami kontrolnymi.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Kinematic compensation and SPC</source>
        <translation>Kompensacja kinematyczna i SPC</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Cannot analyse the circular test: %1</source>
        <translation>Nie można przeanalizować testu okrągłości: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The circular test could not be analysed: %1</source>
        <translation>Nie udało się przeanalizować testu okrągłości: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Repeat the circular test and check its file.</source>
        <translation>Powtórz test okrągłości i sprawdź jego plik.</translation>
    </message>
    <message>
        <location filename="../widgets/report/matchingsection.cpp" line="-390"/>
        <source>SADE (paper settings)</source>
        <translation>SADE (parametry z publikacji)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GA-simplex</source>
        <translation>GA-simpleks</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>closed form (LS optimum)</source>
        <translation>postać zamknięta (optimum MNK)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>minimax</source>
        <translation>minimaks</translation>
    </message>
    <message>
        <location line="+215"/>
        <source>Probe points “%1”, tolerance ±%2 mm</source>
        <translation>Punkty sondowania „%1”, tolerancja ±%2 mm</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Closed form and minimax were run on the %1 points, each re-projected onto the CAD part at every posture until the posture stopped changing. The posture after matching is that of %2; the machine adjustment values are for the study&apos;s %3 machine. Deviation: along the part&apos;s normal at the closest point.</source>
        <translation>Rozwiązanie zamknięte i minimax uruchomiono na %1 punktach, każdy rzutowany na część CAD przy każdym położeniu, aż położenie przestało się zmieniać. Położenie po dopasowaniu pochodzi z %2; wartości nastaw maszyny dotyczą maszyny %3 studium. Odchyłka: wzdłuż normalnej części w najbliższym punkcie.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Every method was run on the %1 points (%2). The posture after matching is that of %3; the machine adjustment values are for the study&apos;s %4 machine. Deviation: %5. Rough matching, SADE, GA-simplex and the machine adjustment as in %6.</source>
        <translation>Każdą metodę uruchomiono na %1 punktach (%2). Położenie po dopasowaniu to położenie z %3; wartości korekty maszyny dotyczą maszyny %4 badania. Odchylenie: %5. Dopasowanie zgrubne, SADE, GA-simplex i korekta maszyny jak w %6.</translation>
    </message>
    <message>
        <location line="+5"/>
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
        <source>along the nominal normal</source>
        <translation>wzdłuż normalnej nominalnej</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance |p − (sRq + t)|</source>
        <translation>odległość |p − (sRq + t)|</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Includes applied effects: %1 (diagnosis, Apply). The nominal points were deformed by them before matching, so the deviations and the machine adjustments below are those of the model with these effects.</source>
        <translation>Zawiera zastosowane efekty: %1 (diagnoza, Zastosuj). Punkty nominalne zostały przez nie odkształcone przed dopasowaniem, więc poniższe odchyłki i nastawienia maszyny dotyczą modelu z tymi efektami.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Before matching</source>
        <translation>Przed dopasowaniem</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+6"/>
        <source>%1 of %2 out of ±%3 mm, max |d| %4 mm</source>
        <translation>%1 z %2 poza ±%3 mm, maks. |d| %4 mm</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>After %1</source>
        <translation>Po %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1; grey: nominal points; lines: deviation vectors ×%2 (both views); large outlined points: out of tolerance.</source>
        <translation>%1; szare: punkty nominalne; linie: wektory odchyłek ×%2 (oba widoki); duże obrysowane punkty: poza tolerancją.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Top view</source>
        <translation>Widok z góry</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Oblique view as in the program</source>
        <translation>Widok ukośny jak w programie</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The nominal is the CAD part “%1” (%2 triangles): the points were matched to its surface, re-projected at each posture. The part is coloured as the nearest probed point, light grey where none is near.</source>
        <translation>Wartością nominalną jest część CAD „%1” (%2 trójkątów): punkty dopasowano do jej powierzchni, rzutując je przy każdym położeniu. Część ma kolor najbliższego punktu pomiarowego, jasnoszara tam, gdzie żadnego nie ma w pobliżu.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>before: deviation (mm), green = within ±%1</source>
        <translation>przed: odchyłka (mm), zielony = w granicach ±%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>after: deviation (mm), green = within ±%1</source>
        <translation>po: odchyłka (mm), zielony = w granicach ±%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../widgets/report/probesection.cpp" line="+315"/>
        <source>surface</source>
        <translation>powierzchnia</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../widgets/report/probesection.cpp" line="-39"/>
        <location line="+39"/>
        <source>points</source>
        <translation>punkty</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMSE before</source>
        <translation>RMSE przed</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max before</source>
        <translation>maks. przed</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out before</source>
        <translation>poza przed</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMSE after</source>
        <translation>RMSE po</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max after</source>
        <translation>maks. po</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out after</source>
        <translation>poza po</translation>
    </message>
    <message>
        <location line="+12"/>
        <location filename="../widgets/report/probesection.cpp" line="+13"/>
        <source>(none)</source>
        <translation>(brak)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>all</source>
        <translation>wszystkie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Deviations before and after %1 (mm)</source>
        <translation>Odchyłki przed i po %1 (mm)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../widgets/report/setupsection.cpp" line="+210"/>
        <source>method</source>
        <translation>metoda</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rx, ry, rz (deg)</source>
        <translation>rx, ry, rz (st.)</translation>
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
        <translation>maks. |d|</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out</source>
        <translation>poza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>evals</source>
        <translation>ocen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>rough</source>
        <translation>zgrubne</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Methods (RMSE and max |d| in mm)</source>
        <translation>Metody (RMSE i maks. |d| w mm)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Locked: %1. The rough stage&apos;s three-point frames cannot hold a lock; its angles are only the start the fine stage moves to the lock values.</source>
        <translation>Zablokowane: %1. Trzypunktowe układy etapu zgrubnego nie mogą utrzymać blokady; ich kąty są tylko punktem startowym, który etap dokładny przesuwa do wartości blokad.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>axis</source>
        <translation>oś</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>unit</source>
        <translation>jednostka</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+127"/>
        <source>frame rotation</source>
        <translation>obrót układu współrzędnych</translation>
    </message>
    <message>
        <location line="-126"/>
        <source>Machine adjustment values (%1%2)</source>
        <translation>Wartości nastawienia maszyny (%1%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, OUTSIDE TRAVEL</source>
        <translation>, POZA ZAKRESEM PRZESUWU</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>control</source>
        <translation>Sterowanie</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>blocks (mm, °)</source>
        <translation>Bloki (mm, °)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 (the study&apos;s control)</source>
        <translation>%1 (sterowanie badania)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The same posture as a controller frame (instead of the axis values; decimals: %1)</source>
        <translation>To samo położenie jako frame sterowania (zamiast wartości osi; miejsca po przecinku: %1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Datum shift then rotation of the working plane; no axis moves (STAY). The whole programs: metrofit-cli match --frame heidenhain|siemens|fanuc.</source>
        <translation>Przesunięcie punktu zerowego, potem obrót płaszczyzny obróbki; żadna oś się nie porusza (STAY). Pełne programy: metrofit-cli match --frame heidenhain|siemens|fanuc.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>round</source>
        <translation>runda</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>max |d| (mm)</source>
        <translation>maks. |d| (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>out of tol.</source>
        <translation>poza tol.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SX, SY, SZ (mm)</source>
        <translation>SX, SY, SZ (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S%1, S%2 (deg)</source>
        <translation>S%1, S%2 (st.)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>in tolerance</source>
        <translation>w tolerancji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped</source>
        <translation>zatrzymano</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Remeasure loop (simulated machine and CMM)</source>
        <translation>Pętla ponownego pomiaru (maszyna symulowana i WMP)</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>Every point within tolerance after %n adjustment(s).</source>
        <translation>
            <numerusform>Każdy punkt w tolerancji po %n korekcie.</numerusform>
            <numerusform>Każdy punkt w tolerancji po %n korektach.</numerusform>
            <numerusform>Każdy punkt w tolerancji po %n korektach.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>FAILED: the best fit leaves points out of tolerance (form error larger than the tolerance); no WCS adjustment can bring them in.</source>
        <translation>NIEPOWODZENIE: najlepsze dopasowanie pozostawia punkty poza tolerancją (błąd kształtu większy niż tolerancja); żadne przesunięcie układu przedmiotu ich nie wprowadzi.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>FAILED: the adjustment is beyond the machine&apos;s travel; the WCS was not moved.</source>
        <translation>NIEPOWODZENIE: korekta wykracza poza zakres ruchu maszyny; układ przedmiotu nie został przesunięty.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>FAILED: still out of tolerance after the last adjustment.</source>
        <translation>NIEPOWODZENIE: nadal poza tolerancją po ostatniej korekcie.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stopped before the end.</source>
        <translation>Zatrzymano przed końcem.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>True remaining error of the simulated part: %1 mm at most, %2 point(s) out of tolerance.</source>
        <translation>Rzeczywisty błąd resztkowy symulowanego przedmiotu: najwyżej %1 mm, punktów poza tolerancją: %2.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The workpiece %1 sits rotated by (%2, %3, %4)° and shifted by (%5, %6, %7) mm; %8 of %9 probed points are out of ±%10 mm before matching, %11 after.</source>
        <translation>Przedmiot %1 jest obrócony o (%2; %3; %4)° i przesunięty o (%5; %6; %7) mm; %8 z %9 zmierzonych punktów leży poza ±%10 mm przed dopasowaniem, %11 po nim.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 machine, enter at the control</source>
        <translation>maszyna %1, wprowadź w sterowaniu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linear axes</source>
        <translation>osie liniowe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rotary axes</source>
        <translation>osie obrotowe</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+4"/>
        <source>max |deviation| %1 mm; %2 of %3 points out of tolerance</source>
        <translation>maks. |odchylenie| %1 mm; %2 z %3 punktów poza tolerancją</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>After the posture adjustment every probed point lies within the tolerance.</source>
        <translation>Po korekcie położenia każdy zmierzony punkt mieści się w tolerancji.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Even after the best posture %1 of %2 points stay out of tolerance: the part itself deviates, not only its posture.</source>
        <translation>Nawet w najlepszym położeniu %1 z %2 punktów pozostaje poza tolerancją: odchyla się sam przedmiot, nie tylko jego położenie.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Do not apply: the adjustment lies outside the axis travel (%1).</source>
        <translation>Nie stosuj: korekta wykracza poza zakres ruchu osi (%1).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Enter the adjustment values at the control, probe the part again and machine when it is within tolerance.</source>
        <translation>Wprowadź wartości korekty w sterowaniu, zmierz przedmiot ponownie i obrabiaj, gdy mieści się w tolerancji.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Enter the adjustment values, probe again, and check the surfaces that stay out of tolerance before machining.</source>
        <translation>Wprowadź wartości korekty, zmierz ponownie i przed obróbką sprawdź powierzchnie, które pozostają poza tolerancją.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Posture matching — before and after</source>
        <translation>Dopasowanie położenia — przed i po</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The matching study&apos;s probe points could not be found.</source>
        <translation>Nie znaleziono punktów sondowania studium dopasowania.</translation>
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
        <translation>Punkty sondowania „%1”</translation>
    </message>
    <message>
        <location line="+21"/>
        <location filename="../widgets/report/setupsection.cpp" line="-96"/>
        <location line="+43"/>
        <location filename="../widgets/report/summarysection.cpp" line="+123"/>
        <location filename="../widgets/report/thermalsection.cpp" line="-284"/>
        <source>file</source>
        <translation>plik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>surfaces</source>
        <translation>powierzchnie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deviation</source>
        <translation>odchyłka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>along the nominal normal, before matching</source>
        <translation>wzdłuż normalnej nominalnej, przed dopasowaniem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance |p − q| (no normals), before matching</source>
        <translation>odległość |p − q| (bez normalnych), przed dopasowaniem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mean |deviation|</source>
        <translation>średnia |odchyłka|</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMS deviation</source>
        <translation>odchyłka RMS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max |deviation|</source>
        <translation>maks. |odchyłka|</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (point %2)</source>
        <translation>%1 (punkt %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+29"/>
        <source>outside ±%1 mm</source>
        <translation>poza ±%1 mm</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>%1 of %2</source>
        <translation>%1 z %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>mean deviation</source>
        <translation>średnia odchyłka</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+5"/>
        <source>Top view (XY)</source>
        <translation>Widok z góry (XY)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Front view (XZ)</source>
        <translation>Widok z przodu (XZ)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>deviation along the normal (mm)</source>
        <translation>odchyłka wzdłuż normalnej (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>distance |p − q| (mm)</source>
        <translation>odległość |p − q| (mm)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>mean deviation (mm)</source>
        <translation>średnia odchyłka (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mean distance (mm)</source>
        <translation>średnia odległość (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max |deviation| (mm)</source>
        <translation>maks. |odchyłka| (mm)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Posture matching — probe points</source>
        <translation>Dopasowanie położenia — punkty sondowania</translation>
    </message>
    <message>
        <location filename="../widgets/report/summarysection.cpp" line="-147"/>
        <source>Metrofit report</source>
        <translation>Raport Metrofit</translation>
    </message>
    <message>
        <location filename="../widgets/report/setupsection.cpp" line="+83"/>
        <location filename="../widgets/report/summarysection.cpp" line="+146"/>
        <source>kind</source>
        <translation>rodzaj</translation>
    </message>
    <message>
        <location filename="../widgets/report/summarysection.cpp" line="-229"/>
        <source>thermal log</source>
        <translation>zapis termiczny</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>probed points</source>
        <translation>zmierzone punkty</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>circular test</source>
        <translation>test okrągłości</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CMM report</source>
        <translation>raport CMM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setup model</source>
        <translation>model ustawień</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feature series</source>
        <translation>seria cech</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DMIS output</source>
        <translation>wynik DMIS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Q-DAS DFQ file</source>
        <translation>plik Q-DAS DFQ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zeiss Calypso table</source>
        <translation>tabela Zeiss Calypso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>QIF results</source>
        <translation>Wyniki QIF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MTConnect log</source>
        <translation>Dziennik MTConnect</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAD part</source>
        <translation>część CAD</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hole table</source>
        <translation>tabela otworów</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>none given</source>
        <translation>nie podano</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Conclusion</source>
        <translation>Wniosek</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Recommendation: %1</source>
        <translation>Zalecenie: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Project “%1”, report made %2 by Metrofit version %3. The project&apos;s description and every dataset&apos;s origin are in the appendix.</source>
        <translation>Projekt „%1”, raport utworzony %2 przez Metrofit w wersji %3. Opis projektu i pochodzenie każdego zbioru danych są w załączniku.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>What each study found</source>
        <translation>Co wykazało każde badanie</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+9"/>
        <location line="+21"/>
        <location line="+14"/>
        <location line="+99"/>
        <source>study</source>
        <translation>badanie</translation>
    </message>
    <message>
        <location line="-143"/>
        <location line="+44"/>
        <source>found</source>
        <translation>wynik</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>recommendation</source>
        <translation>zalecenie</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>change</source>
        <translation>zmiana</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where</source>
        <translation>gdzie</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>What to change on the machine</source>
        <translation>Co zmienić na maszynie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing: no study proposes a change.</source>
        <translation>Nic: żadne badanie nie proponuje zmiany.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>error before</source>
        <translation>błąd przed</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>error after</source>
        <translation>błąd po</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Error before and after</source>
        <translation>Błąd przed i po</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What the closed loop found and leaves unexplained</source>
        <translation>Co znalazła zamknięta pętla i co pozostaje niewyjaśnione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>error before → after</source>
        <translation>błąd przed → po</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>still unexplained</source>
        <translation>wciąż niewyjaśnione</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>What was measured</source>
        <translation>Co zmierzono</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 (%2, %3 rows)</source>
        <translation>%1 (%2, wiersze: %3)</translation>
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
        <translation>%1. Pliki z dnia %2. Licencje: %3.</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n further dataset(s) of the project are used by no study.</source>
        <translation>
            <numerusform>%n dalszy zbiór danych projektu nie jest używany przez żadne badanie.</numerusform>
            <numerusform>%n dalsze zbiory danych projektu nie są używane przez żadne badanie.</numerusform>
            <numerusform>%n dalszych zbiorów danych projektu nie jest używanych przez żadne badanie.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The project declares no study a section of this report could show yet.</source>
        <translation>Projekt nie deklaruje jeszcze żadnego badania, które mógłby pokazać rozdział tego raportu.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1, page %2</source>
        <translation>%1, strona %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Contents: %1.</source>
        <translation>Spis treści: %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>References</source>
        <translation>Bibliografia</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Appendix: data provenance</source>
        <translation>Załącznik: pochodzenie danych</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Every dataset of the project, where it comes from and under which licence; file names are relative to the project&apos;s folder.</source>
        <translation>Każdy zbiór danych projektu, skąd pochodzi i na jakiej licencji; nazwy plików względem folderu projektu.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>rows / points</source>
        <translation>wiersze / punkty</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>file date</source>
        <translation>data pliku</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>licence</source>
        <translation>licencja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>description</source>
        <translation>opis</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Study settings</source>
        <translation>Ustawienia badań</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>settings as the project file holds them</source>
        <translation>ustawienia jak w pliku projektu</translation>
    </message>
    <message>
        <location line="-71"/>
        <source>The project references no datasets.</source>
        <translation>Projekt nie odwołuje się do żadnych zbiorów danych.</translation>
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
        <translation>Bez nazwy</translation>
    </message>
    <message>
        <location filename="../widgets/report/reportpainter.cpp" line="+22"/>
        <source>page %1 of %2</source>
        <translation>strona %1 z %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>page %1</source>
        <translation>strona %1</translation>
    </message>
    <message>
        <location filename="../widgets/report/setupsection.cpp" line="-190"/>
        <source>machine point</source>
        <translation>punkt maszyny</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work offset</source>
        <translation>przesunięcie punktu zerowego</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tool length</source>
        <translation>długość narzędzia</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Setup-data correction</source>
        <translation>Korekcja danych ustawczych</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Model “%1”</source>
        <translation>Model „%1”</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>name</source>
        <translation>nazwa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>setup data</source>
        <translation>dane ustawcze</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1: %2 work offsets, %3 tools, %4 machine points</source>
        <translation>%1: przesunięcia punktu zerowego: %2, narzędzia: %3, punkty maszyny: %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>features</source>
        <translation>elementy geometryczne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dimensions</source>
        <translation>wymiary</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>arcs</source>
        <translation>łuki</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decision space</source>
        <translation>przestrzeń decyzyjna</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>axis %1, grid %2 mm, bounds [%3, %4] mm</source>
        <translation>oś %1, siatka %2 mm, granice [%3; %4] mm</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The project has no CMM report for this model: nothing to correct.</source>
        <translation>Projekt nie ma raportu WMP dla tego modelu: nie ma czego korygować.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Report data “%1”</source>
        <translation>Dane raportu „%1”</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>parts</source>
        <translation>przedmioty</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../widgets/report/thermalsection.cpp" line="+1"/>
        <location line="+184"/>
        <source>rows</source>
        <translation>wiersze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (deviation of a dimension: mean over its rows)</source>
        <translation>%1 (odchyłka wymiaru: średnia z jego wierszy)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>before correction</source>
        <translation>przed korekcją</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>f1 = %1 mm; %2 of %3 mean deviations out of tolerance</source>
        <translation>f1 = %1 mm; %2 z %3 średnich odchyłek poza tolerancją</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (deviation of a dimension: predicted for part %2)</source>
        <translation>%1 (odchyłka wymiaru: przewidywana dla przedmiotu %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>applied effects</source>
        <translation>zastosowane efekty</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (diagnosis, Apply)</source>
        <translation>%1 (diagnoza, Zastosuj)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>model residual</source>
        <translation>residuum modelu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms %1 mm (declared model %2 mm)</source>
        <translation>rms %1 mm (zadeklarowany model %2 mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>last part predicted</source>
        <translation>prognoza ostatniego przedmiotu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms %1 mm from the other parts (declared model %2 mm)</source>
        <translation>rms %1 mm na podstawie pozostałych przedmiotów (zadeklarowany model %2 mm)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Settings</source>
        <translation>Ustawienia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Objectives as in %4, Eq. 6–10: f1 = the smallest unilateral error budget over all dimensions after correction (maximised), f2 = |x| (minimised among the f1-optimal), f = 10 f1 − f2. Exact: LP / MILP on the %1 mm grid (GLPK), then the least-norm correction. CRIPSO: 100 polyps, w = 0.75, c1 = c2 = cos(π/2 Li/L); PSO: 100 particles, asynchronous gbest, same coefficients. Budget %2 solutions, seed %3.</source>
        <translation>Funkcje celu jak w %4, równ. 6–10: f1 = najmniejszy jednostronny budżet błędu po wszystkich wymiarach po korekcie (maksymalizowany), f2 = |x| (minimalizowany wśród f1-optymalnych), f = 10 f1 − f2. Dokładna: LP / MILP na siatce %1 mm (GLPK), potem korekta o najmniejszej normie. CRIPSO: 100 polipów, w = 0,75, c1 = c2 = cos(π/2 Li/L); PSO: 100 cząstek, asynchroniczny gbest, te same współczynniki. Budżet %2 rozwiązań, ziarno %3.</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Error in the setup model of the study %1: %2</source>
        <translation>Błąd w modelu ustawienia badania %1: %2</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>The exact correction of %1 setup data raises the smallest error budget f1 from %2 mm to %3 mm%4; CRIPSO and PSO reach %5 mm and %6 mm.</source>
        <translation>Dokładna korekta %1 danych ustawczych podnosi najmniejszy budżet błędu f1 z %2 mm do %3 mm%4; CRIPSO i PSO osiągają %5 mm i %6 mm.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> (proven optimal)</source>
        <translation> (udowodniona optymalność)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>work offsets</source>
        <translation>przesunięcia punktu zerowego</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tool lengths</source>
        <translation>długości narzędzi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>machine points</source>
        <translation>punkty maszyny</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>add along %1; file %2 (program O7001)</source>
        <translation>dodaj wzdłuż %1; plik %2 (program O7001)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+4"/>
        <source>f1 %1 mm; %2 of %3 dimensions out of tolerance</source>
        <translation>f1 %1 mm; %2 z %3 wymiarów poza tolerancją</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The correction widens the smallest margin to the tolerance limits by %1 mm; %2 of %3 dimensions stay out of tolerance.</source>
        <translation>Korekta zwiększa najmniejszy zapas do granic tolerancji o %1 mm; %2 z %3 wymiarów pozostaje poza tolerancją.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No correction widens the smallest margin: the registers are as good as the measurements allow.</source>
        <translation>Żadna korekta nie zwiększa najmniejszego zapasu: rejestry są tak dobre, jak pozwalają pomiary.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Add the exact corrections to the offset registers (%1, Setup page, Export; Heidenhain and Siemens formats there too), then measure the next part.</source>
        <translation>Dodaj dokładne korekty do rejestrów korekcyjnych (%1, strona Ustawienia, Eksport; tam też formaty Heidenhain i Siemens), a potem zmierz następny przedmiot.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Leave the offset registers as they are.</source>
        <translation>Pozostaw rejestry korekcyjne bez zmian.</translation>
    </message>
    <message>
        <location line="-157"/>
        <source>Convergence</source>
        <translation>Zbieżność</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Comparison</source>
        <translation>Porównanie</translation>
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
        <translation>premia (mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>gap f1 (mm)</source>
        <translation>różnica f1 (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>solutions</source>
        <translation>rozwiązania</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Exact certificate: f1 %1 on the grid, |x| %2 among the f1-optimal corrections (%3 LP / MILP solver calls). Gap f1: the exact f1 minus the method&apos;s.</source>
        <translation>Certyfikat dokładny: f1 %1 na siatce, |x| %2 wśród f1-optymalnych korekcji (wywołania solvera LP / MILP: %3). Różnica f1: dokładne f1 minus f1 metody.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>proven optimal</source>
        <translation>udowodnione optimum</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NOT proven optimal</source>
        <translation>NIE udowodnione optimum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>proven minimal</source>
        <translation>udowodnione minimum</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not proven minimal</source>
        <translation>nieudowodnione minimum</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Corrections (mm, to add to the registers along %1)</source>
        <translation>Korekcje (mm, do dodania do rejestrów wzdłuż %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>setup datum</source>
        <translation>dana ustawcza</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>register</source>
        <translation>rejestr</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exact</source>
        <translation>dokładna</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Margins per dimension, before and after the exact correction</source>
        <translation>Zapasy dla każdego wymiaru, przed i po dokładnej korekcji</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Export for the controller (Fanuc, exact corrections)</source>
        <translation>Eksport dla sterowania (Fanuc, dokładne korekcje)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>metrofit-cli setup --export fanuc writes the same text; Heidenhain, Siemens and CSV are the other formats (see the sign convention in the header).</source>
        <translation>metrofit-cli setup --export fanuc zapisuje ten sam tekst; Heidenhain, Siemens i CSV to pozostałe formaty (patrz konwencja znaków w nagłówku).</translation>
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
            <numerusform>%n temperatura</numerusform>
            <numerusform>%n temperatury</numerusform>
            <numerusform>%n temperatur</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n displacement(s)</source>
        <translation>
            <numerusform>%n przemieszczenie</numerusform>
            <numerusform>%n przemieszczenia</numerusform>
            <numerusform>%n przemieszczeń</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n strain(s)</source>
        <translation>
            <numerusform>%n odkształcenie</numerusform>
            <numerusform>%n odkształcenia</numerusform>
            <numerusform>%n odkształceń</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n speed(s)</source>
        <translation>
            <numerusform>%n prędkość</numerusform>
            <numerusform>%n prędkości</numerusform>
            <numerusform>%n prędkości</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n other</source>
        <translation>
            <numerusform>%n inny</numerusform>
            <numerusform>%n inne</numerusform>
            <numerusform>%n innych</numerusform>
        </translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 heating, %2 cooling, from the speed channel %3 (running = heating)</source>
        <translation>nagrzewanie: %1, chłodzenie: %2, z kanału prędkości %3 (praca = nagrzewanie)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 heating, %2 cooling, from the slope of the mean temperature</source>
        <translation>nagrzewanie: %1, chłodzenie: %2, z nachylenia średniej temperatury</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>none detected</source>
        <translation>nie wykryto</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Thermal log “%1”</source>
        <translation>Rejestr termiczny „%1”</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1, every %2 (median), time column %3</source>
        <translation>%1, co %2 (mediana), kolumna czasu %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>duration</source>
        <translation>czas trwania</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>channels</source>
        <translation>kanały</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phases</source>
        <translation>fazy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chart</source>
        <translation>wykres</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 of %2 channels shown; the table lists all</source>
        <translation>Pokazano %1 z %2 kanałów; tabela zawiera wszystkie</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>channel</source>
        <translation>kanał</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>quantity</source>
        <translation>wielkość</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>max</source>
        <translation>maks.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>in chart</source>
        <translation>na wykresie</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1 → %2%3</source>
        <translation>%1 → %2%3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>used by %1 (held-out error %2)</source>
        <translation>używane przez %1 (błąd danych testowych %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not used by %1 (held-out error would rise: %2)</source>
        <translation>nieużywane przez %1 (błąd danych testowych wzrósłby: %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not used by %1 (held-out error would not fall: %2)</source>
        <translation>nieużywane przez %1 (błąd danych testowych nie zmalałby: %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Applied effects %1 (added with Apply on the diagnosis page; each model is fitted with and without them and keeps the lower held-out error): %2.</source>
        <translation>Zastosowane efekty %1 (dodane przyciskiem „Zastosuj do modelu” na stronie diagnozy; każdy model jest dopasowywany z nimi i bez nich i zachowuje mniejszy błąd danych testowych): %2.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Hysteresis</source>
        <translation>Histereza</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No hysteresis analysis: %1</source>
        <translation>Brak analizy histerezy: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 against each sensor (Fig. 9 of %5): heating runs (the change of %1 grows, %2 rows) and cooling runs (%3 rows) in the colours of the trend chart&apos;s phases. Loop area by the shoelace formula; lag: the time constant of a first-order lag between sensor and displacement (&gt; 0: the sensor lags).%4</source>
        <translation>%1 względem każdego czujnika (rys. 9 w %5): odcinki nagrzewania (zmiana %1 rośnie, wiersze: %2) i chłodzenia (wiersze: %3) w kolorach faz wykresu przebiegu. Pole pętli wzorem Gaussa; opóźnienie: stała czasowa członu inercyjnego pierwszego rzędu między czujnikiem a przemieszczeniem (&gt; 0: czujnik się opóźnia).%4</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Every row of the log is fitted, as on the Thermal page (trained there %1, stored in the project with these settings and this data), so the report chooses the page&apos;s model with the page&apos;s figures.</source>
        <translation>Każdy wiersz rejestru jest dopasowywany, jak na stronie Termika (wytrenowano tam %1, zapisano w projekcie z tymi ustawieniami i tymi danymi), więc raport wybiera model strony z jej wartościami.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>To keep the report&apos;s run time short, this %1-row log is fitted on every %2th row (%3 rows); the GUI and metrofit-cli fit all rows and may choose another model. Train the models on the Thermal page and save the project: the report then fits every row and shows the page&apos;s choice.</source>
        <translation>Aby skrócić czas tworzenia raportu, ten rejestr o %1 wierszach jest dopasowywany co %2. wiersz (%3 wierszy); GUI i metrofit-cli dopasowują wszystkie wiersze i mogą wybrać inny model. Wytrenuj modele na stronie Termika i zapisz projekt: raport dopasuje wtedy każdy wiersz i pokaże wybór strony.</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>not fitted: %1</source>
        <translation>nie dopasowano: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: not fitted</source>
        <translation>%1: nie dopasowano</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Performance indices (Table 4 of %1): R correlation, RMSE, E Nash-Sutcliffe efficiency, band = largest |residual|. A model is usable for compensation only when on the held-out rows it does not diverge (RMSE at most %2 × the largest error), E ≥ %3 and R ≥ %4.</source>
        <translation>Wskaźniki jakości (tabela 4 w %1): R korelacja, RMSE, E sprawność Nasha-Sutcliffe’a, pasmo = największe |residuum|. Model nadaje się do kompensacji tylko wtedy, gdy na odłożonych wierszach nie rozbiega się (RMSE co najwyżej %2 × największy błąd), E ≥ %3 i R ≥ %4.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Modular models (%1, Section 4.3)</source>
        <translation>Modele modułowe (%1, rozdział 4.3)</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>not fitted</source>
        <translation>nie dopasowano</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 not fitted: %2.</source>
        <translation>%1 nie dopasowano: %2.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>modules, summed (distributed lag)</source>
        <translation>moduły, zsumowane (rozłożone opóźnienie)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 with inputs %2, up to %3 %4</source>
        <translation>%1 z wejściami %2, do %3 %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> (identified again on %1)</source>
        <translation> (ponownie zidentyfikowany na %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Module by module (the last row and the dotted curves): each module is identified on its own test alone, with the channels its own heating moves at least twice as much as the other test&apos;s, by the distributed-lag model, and the combined test is predicted as the sum of the modules, so that one module can be identified again without the others: %1.</source>
        <translation>Moduł po module (ostatni wiersz i kropkowane krzywe): każdy moduł jest identyfikowany wyłącznie na własnym teście, z kanałami, które jego własne nagrzewanie zmienia co najmniej dwa razy bardziej niż drugi test, modelem z rozłożonym opóźnieniem, a test łączony jest przewidywany jako suma modułów, dzięki czemu jeden moduł można zidentyfikować ponownie bez pozostałych: %1.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Module by module: not identified (%1).</source>
        <translation>Moduł po module: nie zidentyfikowano (%1).</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The thermal models could not be fitted: %1</source>
        <translation>Nie udało się dopasować modeli termicznych: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Check the thermal study&apos;s target and inputs against the log.</source>
        <translation>Sprawdź wielkość docelową i wejścia badania termicznego względem zapisu.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 could not be fitted (%2)</source>
        <translation>%1 nie dało się dopasować (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is not usable (%2)</source>
        <translation>%1 nie nadaje się do użycia (%2)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 varies by RMS %2%3 (peak %4%3) on the held-out rows</source>
        <translation>%1 zmienia się na odłożonych wierszach o RMS %2%3 (szczyt %4%3)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Best usable model of %1: %2, held-out RMSE %3%4, residual band ±%5%4.</source>
        <translation>Najlepszy użyteczny model dla %1: %2, RMSE na odłożonych %3%4, pasmo residuów ±%5%4.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RMS %1%2 (band ±%3%2) left with %4</source>
        <translation>RMS %1%2 (pasmo ±%3%2) pozostaje z %4</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>thermal compensation of %1</source>
        <translation>kompensacja termiczna %1</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>model fitted on %1; a grey model has no form a control runs: fit linear, lag or dlag to export it</source>
        <translation>model dopasowany na %1; model szary nie ma postaci, którą wykonuje sterowanie: do eksportu dopasuj linear, lag lub dlag</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>model fitted on %1; export it for the control on the Thermal page (Export compensation) or with metrofit-cli thermal export --format %2</source>
        <translation>model dopasowany na %1; eksport dla sterowania na stronie Termika (Eksportuj kompensację) lub poleceniem metrofit-cli thermal export --format %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 predicts %2 on rows it was not fitted on to RMS %3%4, from RMS %5%4 without compensation.</source>
        <translation>%1 przewiduje %2 na wierszach, na których nie był dopasowany, z RMS %3%4 wobec RMS %5%4 bez kompensacji.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Compensate %1 with %2; do not use the models marked not usable.</source>
        <translation>Kompensuj %1 za pomocą %2; nie używaj modeli oznaczonych jako nieużyteczne.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No model of %1 passes the held-out test.</source>
        <translation>Żaden model dla %1 nie przechodzi testu na odłożonych wierszach.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Do not compensate with these models. Record a longer test covering heating and cooling, add sensors near the heat sources, and use the closed loop (diagnosis) to find the lag or inputs the model lacks.</source>
        <translation>Nie kompensuj tymi modelami. Zarejestruj dłuższy test obejmujący nagrzewanie i chłodzenie, dodaj czujniki blisko źródeł ciepła i użyj zamkniętej pętli (diagnozy), aby znaleźć opóźnienie lub wejścia, których brakuje modelowi.</translation>
    </message>
    <message>
        <location line="-339"/>
        <source>Charts of the first %1 of %2 sensors; the table lists all.</source>
        <translation>Wykresy pierwszych %1 z %2 czujników; tabela zawiera wszystkie.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>sensor</source>
        <translation>czujnik</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>loop area</source>
        <translation>pole pętli</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>loop / ranges</source>
        <translation>pętla / rozstępy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lag τ (min)</source>
        <translation>opóźnienie τ (min)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R² with lag</source>
        <translation>R² z opóźnieniem</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R² static</source>
        <translation>R² statyczny</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Thermal error models</source>
        <translation>Modele błędu termicznego</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>GNNMCI(1,N) (PSO, 90 particles, 100 iterations, seed %1), GMC(1,N) (least squares) and the MLP (%2-10-1, Levenberg-Marquardt, seed %1) predict %3 from %4; each is fitted on the first %5 % of the rows and tested on the rest (held out, shaded).</source>
        <translation>GNNMCI(1,N) (PSO, 90 cząstek, 100 iteracji, ziarno %1), GMC(1,N) (najmniejsze kwadraty) i MLP (%2-10-1, Levenberg-Marquardt, ziarno %1) przewidują %3 na podstawie %4; każdy jest dopasowany na pierwszych %5 % wierszy i testowany na reszcie (dane testowe, zacienione).</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>The models could not be fitted: %1</source>
        <translation>Nie można było dopasować modeli: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>residual = measured − model</source>
        <translation>residuum = zmierzone − model</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+98"/>
        <source>model</source>
        <translation>model</translation>
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
        <translation>pasmo (%1)</translation>
    </message>
    <message>
        <location line="-97"/>
        <source>verdict</source>
        <translation>ocena</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 PSO iterations, Eq. 2.9 %2 → %3</source>
        <translation>iteracje PSO: %1, równ. 2.9 %2 → %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>least squares, b1 = %1</source>
        <translation>najmniejsze kwadraty, b1 = %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>least squares, unstable: b1 = %1 ≤ 0</source>
        <translation>najmniejsze kwadraty, niestabilny: b1 = %1 ≤ 0</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 LM epochs (%2)</source>
        <translation>epoki LM: %1 (%2)</translation>
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
        <translation>rozbieżny</translation>
    </message>
    <message>
        <location line="-60"/>
        <source>fit, %1</source>
        <translation>dopasowanie, %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>held out, %1</source>
        <translation>dane testowe, %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Training: %1.</source>
        <translation>Trenowanie: %1.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The modular case could not be computed: %1</source>
        <translation>Nie można było obliczyć przypadku modułowego: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Each model is fitted on the Z-heating test (%1) and the C-heating test (%2) together and predicts the combined helical test (%3), which it has not seen. Target %4, inputs %5, seed 1. Error reduction as the paper states it: 1 − max|residual| / max|error|, and by RMS.</source>
        <translation>Każdy model jest dopasowywany łącznie na teście nagrzewania Z (%1) i teście nagrzewania C (%2) i przewiduje łączony test śrubowy (%3), którego nie widział. Wielkość docelowa %4, wejścia %5, ziarno 1. Redukcja błędu jak w publikacji: 1 − max|residuum| / max|błąd| oraz według RMS.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>less, peak</source>
        <translation>mniej, szczyt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>less, RMS</source>
        <translation>mniej, RMS</translation>
    </message>
</context>
<context>
    <name>metrofit::ReportExporter</name>
    <message>
        <location filename="../app/gui/reportexporter.cpp" line="+39"/>
        <source>the unsaved project</source>
        <translation>niezapisany projekt</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot prepare the report: %1</source>
        <translation>Nie można przygotować raportu: %1</translation>
    </message>
    <message>
        <location line="+20"/>
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
    <name>metrofit::ReportModelDialog</name>
    <message>
        <location filename="../widgets/setup/reportmodeldialog.cpp" line="+40"/>
        <source>Create setup model from report %1</source>
        <translation>Utwórz model ustawienia z raportu %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add report features to setup model</source>
        <translation>Dodaj elementy raportu do modelu ustawienia</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The %1 “%2” measures these characteristics. The checked ones become the dimensions of a new setup model, each under a feature node; draw the real relation graph in the Graph tab afterwards.</source>
        <translation>%1 „%2” mierzy te charakterystyki. Zaznaczone stają się wymiarami nowego modelu ustawienia, każdy pod węzłem elementu; właściwy graf relacji narysuj potem w zakładce Graf.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The %1 “%2” measures these characteristics. The checked ones are added to the setup model “%3” as dimensions; those it reads already are marked.</source>
        <translation>%1 „%2” mierzy te charakterystyki. Zaznaczone zostaną dodane do modelu ustawienia „%3” jako wymiary; te, które już odczytuje, są oznaczone.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Feature</source>
        <translation>Element</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Characteristic</source>
        <translation>Charakterystyka</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Nominal</source>
        <translation>Nominał</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lower tol.</source>
        <translation>Tol. dolna</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Upper tol.</source>
        <translation>Tol. górna</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>State</source>
        <translation>Stan</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>in the model (%1)</source>
        <translation>w modelu (%1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the report prints no nominal for it</source>
        <translation>raport nie podaje dla niej wartości nominalnej</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an angle (deg), not a length a setup correction moves</source>
        <translation>kąt (°), a nie długość, którą przesuwa korekcja danych ustawczych</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot be used: %1</source>
        <translation>nie do użycia: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no tolerance printed: takes ± the value below</source>
        <translation>brak tolerancji w raporcie: przyjmuje ± wartość poniżej</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Check &amp;all</source>
        <translation>Zaznacz &amp;wszystkie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check &amp;none</source>
        <translation>&amp;Odznacz wszystkie</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The machine axis the corrections act along</source>
        <translation>Oś maszyny, wzdłuż której działają korekcje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model &amp;name:</source>
        <translation>&amp;Nazwa modelu:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;xis:</source>
        <translation>O&amp;ś:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>(none: draw the arcs yourself)</source>
        <translation>(brak: łuki narysuj sam)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Each new feature gets an arc (+1) from this setup datum, so the model can run at once; change the arcs in the Graph tab</source>
        <translation>Każdy nowy element dostaje łuk (+1) od tej danej ustawienia, więc model można od razu obliczyć; łuki zmienisz w zakładce Graf</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Connect new features to:</source>
        <translation>&amp;Połącz nowe elementy z:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>± limits for values the report prints no tolerance for (0: such values cannot be added)</source>
        <translation>Granice ± dla wartości, dla których raport nie podaje tolerancji (0: takich wartości nie można dodać)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Tolerance where the report gives none: ±</source>
        <translation>&amp;Tolerancja, gdy raport jej nie podaje: ±</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Create model</source>
        <translation>Utwórz model</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Add to model</source>
        <translation>Dodaj do modelu</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Check the characteristics to add.</source>
        <translation>Zaznacz charakterystyki do dodania.</translation>
    </message>
    <message numerus="yes">
        <location line="+26"/>
        <source>%n dimension(s) to add; the model will have %1 features and %2 dimensions.</source>
        <translation>
            <numerusform>%n wymiar do dodania; model będzie miał %1 elementów i %2 wymiarów.</numerusform>
            <numerusform>%n wymiary do dodania; model będzie miał %1 elementów i %2 wymiarów.</numerusform>
            <numerusform>%n wymiarów do dodania; model będzie miał %1 elementów i %2 wymiarów.</numerusform>
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
        <translation>test F</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>time</source>
        <translation>czas</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>file row</source>
        <translation>wiersz pliku</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>path angle</source>
        <translation>kąt na torze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>loop direction</source>
        <translation>kierunek obiegu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>samples since reversal</source>
        <translation>próbki od nawrotu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>along the normal</source>
        <translation>wzdłuż normalnej</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part</source>
        <translation>przedmiot</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dimension</source>
        <translation>wymiar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>surface</source>
        <translation>powierzchnia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>normal %1</source>
        <translation>normalna %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>surface %1</source>
        <translation>powierzchnia %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+140"/>
        <source>dimension %1</source>
        <translation>wymiar %1</translation>
    </message>
    <message>
        <location line="-133"/>
        <source>time</source>
        <comment>in a sentence</comment>
        <translation>czasu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the order of the rows in the file</source>
        <translation>kolejności wierszy w pliku</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the path angle</source>
        <translation>kąta na torze</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the direction of the loop (counter-clockwise or clockwise)</source>
        <translation>kierunku obiegu (przeciwnie do ruchu wskazówek zegara lub zgodnie z nim)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the number of samples since an axis reversed</source>
        <translation>liczby próbek od nawrotu osi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the nominal %1 coordinate</source>
        <translation>nominalnej współrzędnej %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the position along the nominal normal</source>
        <translation>położenia wzdłuż nominalnej normalnej</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the part</source>
        <translation>przedmiotu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the dimension</source>
        <translation>wymiaru</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the surface</source>
        <translation>powierzchni</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the %1 component of the nominal normal</source>
        <translation>składowej %1 nominalnej normalnej</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the position on surface %1</source>
        <translation>położenia na powierzchni %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dimension %1</source>
        <comment>in a sentence</comment>
        <translation>wymiaru %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>column %1</source>
        <translation>kolumny %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>linear</source>
        <translation>liniowa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>smooth</source>
        <translation>gładka</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>step</source>
        <translation>skok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>periodic</source>
        <translation>okresowa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per level</source>
        <translation>na poziom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spike</source>
        <translation>impuls</translation>
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
        <translation>okresowa, okres %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>a cycle with a period of %1</source>
        <translation>cykl o okresie %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a linear trend</source>
        <translation>trend liniowy</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a smooth curve</source>
        <translation>gładka krzywa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a step</source>
        <translation>skok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a step at %1</source>
        <translation>skok przy %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a periodic pattern</source>
        <translation>wzór okresowy</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a different level per group</source>
        <translation>inny poziom w każdej grupie</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1 (%2, %3 % of the residual variance)</source>
        <translation>%1 (%2, %3 % wariancji residuum)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>white: no test finds structure</source>
        <translation>białe: żaden test nie znajduje struktury</translation>
    </message>
    <message>
        <location line="+102"/>
        <source>Warning: the held-out error rose from %1 to %2 %3 with the accepted effects. They describe the fit rows but do not carry over to the rows they did not see: do not compensate with them.</source>
        <translation>Ostrzeżenie: błąd wierszy wstrzymanych wzrósł z przyjętymi efektami z %1 do %2 %3. Opisują one wiersze dopasowania, ale nie przenoszą się na wiersze, których nie widziały: nie kompensować nimi.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>On the held-out rows, which only report the error, the residual looks like noise as well.</source>
        <translation>W wierszach wstrzymanych, które tylko raportują błąd, reszta również wygląda jak szum.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>On the held-out rows, which only report the error, the residual still depends on %1: the model misses something there that the fit rows did not show.</source>
        <translation>W wierszach wstrzymanych, które tylko raportują błąd, reszta nadal zależy od %1: modelowi brakuje tam czegoś, czego wiersze dopasowania nie pokazały.</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n held-out measurement(s) left out of the held-out error as gross errors: %1.</source>
        <translation>
            <numerusform>%n wstrzymany pomiar pominięty w błędzie wierszy wstrzymanych jako błąd gruby: %1.</numerusform>
            <numerusform>%n wstrzymane pomiary pominięte w błędzie wierszy wstrzymanych jako błędy grube: %1.</numerusform>
            <numerusform>%n wstrzymanych pomiarów pominiętych w błędzie wierszy wstrzymanych jako błędy grube: %1.</numerusform>
        </translation>
    </message>
    <message>
        <location line="-134"/>
        <source>not white: still depends on %1</source>
        <translation>nie białe: wciąż zależy od zmiennych: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not white: the tests find structure that no single variable explains</source>
        <translation>nie białe: testy znajdują strukturę, której nie wyjaśnia żadna pojedyncza zmienna</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>row %1</source>
        <translation>wiersz %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part %1</source>
        <translation>przedmiot %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>point %1</source>
        <translation>punkt %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>observation %1</source>
        <translation>obserwacja %1</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>What is left unexplained: nothing that the tests can find. None of the %n test(s) of the final residual (against every variable the data offer, and of its serial correlation) finds a dependence at the %1 % family-wise level: the residual looks like noise.</source>
        <translation>
            <numerusform>Co pozostaje niewyjaśnione: nic, co testy potrafią znaleźć. %n test końcowego residuum (względem każdej zmiennej danych i na korelację szeregową) nie znajduje zależności na poziomie %1 % dla całej rodziny testów: residuum wygląda jak szum.</numerusform>
            <numerusform>Co pozostaje niewyjaśnione: nic, co testy potrafią znaleźć. Żaden z %n testów końcowego residuum (względem każdej zmiennej danych i na korelację szeregową) nie znajduje zależności na poziomie %1 % dla całej rodziny testów: residuum wygląda jak szum.</numerusform>
            <numerusform>Co pozostaje niewyjaśnione: nic, co testy potrafią znaleźć. Żaden z %n testów końcowego residuum (względem każdej zmiennej danych i na korelację szeregową) nie znajduje zależności na poziomie %1 % dla całej rodziny testów: residuum wygląda jak szum.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+79"/>
        <source>%1 (%2, %3 % of the residual variance, p = %4)</source>
        <translation>%1 (%2, %3 % wariancji residuum, p = %4)</translation>
    </message>
    <message>
        <location line="-70"/>
        <source>%1 and %2</source>
        <translation>%1 oraz %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What is left unexplained: the final residual still depends on %1. No effect of the catalogue explains this (tests at the %2 % family-wise level).</source>
        <translation>Co pozostaje niewyjaśnione: końcowe residuum wciąż zależy od %1. Żaden efekt z katalogu tego nie wyjaśnia (testy na poziomie %2 % dla całej rodziny testów).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What is left unexplained: the final residual is serially correlated in the order of %1 (Ljung-Box test, p = %2), but no single variable of the data explains it.</source>
        <translation>Co pozostaje niewyjaśnione: końcowe residuum jest skorelowane szeregowo w kolejności %1 (test Ljung-Boxa, p = %2), ale żadna pojedyncza zmienna danych tego nie wyjaśnia.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>What is left unexplained: the tests find structure in the final residual at the %1 % family-wise level that no single variable explains.</source>
        <translation>Co pozostaje niewyjaśnione: testy znajdują w końcowym residuum, na poziomie %1 % dla całej rodziny testów, strukturę, której nie wyjaśnia żadna pojedyncza zmienna.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 in %2</source>
        <translation>%1 względem %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No effect of the catalogue explains part of this structure, so the model was given a generic term for it instead of a wrong name: %1.</source>
        <translation>Żaden efekt z katalogu nie wyjaśnia części tej struktury, więc model otrzymał dla niej człon ogólny zamiast błędnej nazwy: %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No measurement was excluded as a gross error (robust z above %1).</source>
        <translation>Żaden pomiar nie został wykluczony jako błąd gruby (odporne z powyżej %1).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No measurement was excluded as a gross error.</source>
        <translation>Żaden pomiar nie został wykluczony jako błąd gruby.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 (residual %2 %3, robust z %4)</source>
        <translation>%1 (residuum %2 %3, odporne z %4)</translation>
    </message>
    <message numerus="yes">
        <location line="-95"/>
        <location line="+100"/>
        <source> and %n more</source>
        <translation>
            <numerusform> i %n kolejny</numerusform>
            <numerusform> i %n kolejne</numerusform>
            <numerusform> i %n kolejnych</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n measurement(s) excluded from the fit as gross errors (robust z above %1): %2.</source>
        <translation>
            <numerusform>%n pomiar wykluczony z dopasowania jako błąd gruby (odporne z powyżej %1): %2.</numerusform>
            <numerusform>%n pomiary wykluczone z dopasowania jako błędy grube (odporne z powyżej %1): %2.</numerusform>
            <numerusform>%n pomiarów wykluczonych z dopasowania jako błędy grube (odporne z powyżej %1): %2.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>metrofit::ResidualCheckView</name>
    <message>
        <location filename="../widgets/diagnose/residualcheckview.cpp" line="+122"/>
        <source>Final residual against %1</source>
        <translation>Końcowe residuum względem %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Final residual against %1 with the generic fit (%2)</source>
        <translation>Końcowe residuum względem %1 z dopasowaniem ogólnym (%2)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+163"/>
        <location line="+283"/>
        <source>residual</source>
        <translation>residuum</translation>
    </message>
    <message>
        <location line="-445"/>
        <source>residual (%1)</source>
        <translation>residuum (%1)</translation>
    </message>
    <message>
        <location line="+167"/>
        <source>generic fit</source>
        <translation>dopasowanie ogólne</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>generic fit, %1</source>
        <translation>dopasowanie ogólne, %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+290"/>
        <source>excluded outliers</source>
        <translation>wykluczone wartości odstające</translation>
    </message>
    <message>
        <location line="-249"/>
        <location line="+143"/>
        <source>What the residual still depends on (strongest first):</source>
        <translation>Od czego residuum wciąż zależy (najsilniejsze najpierw):</translation>
    </message>
    <message>
        <location line="-142"/>
        <source>Outliers excluded from the fit:</source>
        <translation>Wartości odstające wykluczone z dopasowania:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tests of the final residual:</source>
        <translation>Testy końcowego residuum:</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The final residual (after every accepted effect, outliers excluded) is white when no test finds structure at the family-wise level (Holm&apos;s procedure over all tests)</source>
        <translation>Końcowe residuum (po wszystkich przyjętych efektach, bez wartości odstających) jest białe, gdy żaden test nie znajduje struktury na poziomie dla całej rodziny testów (procedura Holma dla wszystkich testów)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Variable</source>
        <translation>Zmienna</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+11"/>
        <source>Form</source>
        <translation>Postać</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Share (%)</source>
        <translation>Udział (%)</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+12"/>
        <source>p-value</source>
        <translation>wartość p</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Per variable with a rejected test its strongest form; share = part of the residual variance the form explains</source>
        <translation>Dla każdej zmiennej z odrzuconym testem jej najsilniejsza postać; udział = część wariancji residuum wyjaśniona przez tę postać</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Row</source>
        <translation>Wiersz</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Part</source>
        <translation>Przedmiot</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Dimension</source>
        <translation>Wymiar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Id</source>
        <translation>Identyfikator</translation>
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
        <translation>Odporne z</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Observations whose robust z (|r - median| / (1.4826 MAD)) is above the threshold: gross errors, excluded and the model refitted without them</source>
        <translation>Obserwacje, których odporne z (|r - mediana| / (1,4826 MAD)) przekracza próg: błędy grube, wykluczone, a model dopasowany ponownie bez nich</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Test</source>
        <translation>Test</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Order / variable</source>
        <translation>Kolejność / zmienna</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Statistic</source>
        <translation>Statystyka</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>df</source>
        <translation>st. sw.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rejected</source>
        <translation>Odrzucony</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ljung-Box: serial correlation of the residual in that order (chi-square); F test: the residual against the variable in that form (nested models). Rejected: by Holm&apos;s procedure at the family-wise level</source>
        <translation>Ljung-Box: korelacja szeregowa residuum w tej kolejności (chi-kwadrat); test F: residuum względem zmiennej w tej postaci (modele zagnieżdżone). Odrzucony: procedurą Holma na poziomie dla całej rodziny testów</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Residual check: run the diagnosis (Ctrl+R).</source>
        <translation>Sprawdzenie residuów: uruchom diagnozę (Ctrl+R).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Final residual: run the diagnosis (Ctrl+R)</source>
        <translation>Końcowe residuum: uruchom diagnozę (Ctrl+R)</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+1"/>
        <source>This diagnosis has no residual check.</source>
        <translation>Ta diagnoza nie ma sprawdzenia residuów.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>What the residual still depends on: nothing found.</source>
        <translation>Od czego residuum wciąż zależy: nic nie znaleziono.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Outliers: none (robust z threshold %1).</source>
        <translation>Wartości odstające: brak (próg odpornego z %1).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Outliers: none.</source>
        <translation>Wartości odstające: brak.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outliers excluded from the fit (robust z above %1):</source>
        <translation>Wartości odstające wykluczone z dopasowania (odporne z powyżej %1):</translation>
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
            <numerusform>Testy końcowego residuum (%n test, obserwacji: %1; odrzucone procedurą Holma na poziomie %2 % dla całej rodziny):</numerusform>
            <numerusform>Testy końcowego residuum (%n testy, obserwacji: %1; odrzucone procedurą Holma na poziomie %2 % dla całej rodziny):</numerusform>
            <numerusform>Testy końcowego residuum (%n testów, obserwacji: %1; odrzucone procedurą Holma na poziomie %2 % dla całej rodziny):</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rejected at %1 %</source>
        <translation>Odrzucony przy %1 %</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>The final residual is white: nothing left to plot</source>
        <translation>Końcowe residuum jest białe: nic do pokazania</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No single variable explains the structure left</source>
        <translation>Żadna pojedyncza zmienna nie wyjaśnia pozostałej struktury</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>generic fit (%1)</source>
        <translation>dopasowanie ogólne (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>generic fit (%1), %2</source>
        <translation>dopasowanie ogólne (%1), %2</translation>
    </message>
    <message numerus="yes">
        <location line="+48"/>
        <source>(index of %n level(s))</source>
        <translation>
            <numerusform>(indeks %n poziomu)</numerusform>
            <numerusform>(indeks %n poziomów)</numerusform>
            <numerusform>(indeks %n poziomów)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>metrofit::ResidualPlot</name>
    <message>
        <location filename="../widgets/diagnose/residualplot.cpp" line="-283"/>
        <source>before the effect</source>
        <translation>przed efektem</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>after</source>
        <translation>po</translation>
    </message>
    <message>
        <location line="+22"/>
        <source> (arrows × %1)</source>
        <translation> (strzałki × %1)</translation>
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
        <translation>Wykres residuów: uruchom diagnozę (Ctrl+R)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>residual before the effect</source>
        <translation>residuum przed efektem</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>after</source>
        <translation>po</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupCharts</name>
    <message>
        <location filename="../widgets/setup/setupcharts.cpp" line="+60"/>
        <source>exact</source>
        <translation>dokładna</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1, seed %2</source>
        <translation>%1, ziarno %2</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>solid: f1</source>
        <translation>ciągła: f1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dashed: f2 = |x|</source>
        <translation>kreskowana: f2 = |x|</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dotted: f = 10 f1 − f2 (right axis)</source>
        <translation>kropkowana: f = 10 f1 − f2 (prawa oś)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>solutions evaluated</source>
        <translation>ocenione rozwiązania</translation>
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
        <translation>dokładne optimum f1 = %1 mm</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>exact f = %1</source>
        <translation>dokładne f = %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>measurement set, sorted by f1 before correction</source>
        <translation>zestaw pomiarów, sortowany wg f1 przed korekcją</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>before correction</source>
        <translation>przed korekcją</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exact optimum</source>
        <translation>dokładne optimum</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 trials</source>
        <translation>próby: %1</translation>
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
        <translation>Wielkość wektora korekcji, mm (minimalizowana wśród f1-optymalnych)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The single objective the metaheuristics maximise (right axis)</source>
        <translation>Pojedyncza funkcja celu maksymalizowana przez metaheurystyki (prawa oś)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Best solution so far against the number of solutions evaluated.</source>
        <translation>Najlepsze dotąd rozwiązanie wobec liczby ocenionych.</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupGraphEditor</name>
    <message>
        <location filename="../widgets/setup/setupgrapheditor.cpp" line="+94"/>
        <source>Add node…</source>
        <translation>Dodaj węzeł…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Add a machine point, work offset, tool, feature or dimension</source>
        <translation>Dodaj punkt maszyny, przesunięcie punktu zerowego, narzędzie, element geometryczny lub wymiar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add arc…</source>
        <translation>Dodaj łuk…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Add an arc with weight +1 or −1</source>
        <translation>Dodaj łuk o wadze +1 lub −1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Edit…</source>
        <translation>Edytuj…</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rename the selected node or change its kind; flip the weight of the selected arc</source>
        <translation>Zmień nazwę lub rodzaj zaznaczonego węzła; odwróć wagę zaznaczonego łuku</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove</source>
        <translation>Usuń</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Remove the selected node (with its arcs) or arc</source>
        <translation>Usuń zaznaczony węzeł (wraz z łukami) lub łuk</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Undo</source>
        <translation>Cofnij</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Redo</source>
        <translation>Ponów</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Undo the last edit of the graph (Ctrl+Z while the graph has the focus)</source>
        <translation>Cofnij ostatnią zmianę grafu (Ctrl+Z, gdy graf ma fokus)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Redo (Ctrl+Shift+Z while the graph has the focus)</source>
        <translation>Ponów (Ctrl+Shift+Z, gdy graf ma fokus)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Zoom in</source>
        <translation>Powiększ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Zoom in (Ctrl+wheel)</source>
        <translation>Powiększ (Ctrl+kółko)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Zoom out</source>
        <translation>Pomniejsz</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Zoom out (Ctrl+wheel)</source>
        <translation>Pomniejsz (Ctrl+kółko)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fit</source>
        <translation>Dopasuj</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fit the whole graph into the view</source>
        <translation>Dopasuj cały graf do widoku</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rows</source>
        <translation>Wiersze</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Levels in rows instead of columns</source>
        <translation>Poziomy w wierszach zamiast w kolumnach</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export SVG…</source>
        <translation>Eksportuj SVG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the graph as an SVG drawing</source>
        <translation>Zapisz graf jako rysunek SVG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export PNG…</source>
        <translation>Eksportuj PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the graph as a PNG image</source>
        <translation>Zapisz graf jako obraz PNG</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export</source>
        <translation>Eksportuj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the graph as an SVG drawing or a PNG image</source>
        <translation>Zapisz graf jako rysunek SVG lub obraz PNG</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Dimension</source>
        <translation>Wymiar</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Nominal
(mm)</source>
        <translation>Nominalny
(mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lower
(mm)</source>
        <translation>Dolna
(mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Upper
(mm)</source>
        <translation>Górna
(mm)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Report
feature</source>
        <translation>Element
raportu</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+152"/>
        <source>What the CMM report calls the dimension (feature:value, a DMIS label); empty: its id</source>
        <translation>Jak raport CMM nazywa wymiar (element:wartość, etykieta DMIS); puste: jego identyfikator</translation>
    </message>
    <message>
        <location line="-150"/>
        <source>Lower tolerance limit relative to the nominal, mm</source>
        <translation>Dolna granica tolerancji względem wartości nominalnej, mm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Upper tolerance limit relative to the nominal, mm</source>
        <translation>Górna granica tolerancji względem wartości nominalnej, mm</translation>
    </message>
    <message numerus="yes">
        <location line="+68"/>
        <source>… and %n more problem(s)</source>
        <translation>
            <numerusform>… i jeszcze %n problem</numerusform>
            <numerusform>… i jeszcze %n problemy</numerusform>
            <numerusform>… i jeszcze %n problemów</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>The model has %n problem(s) (outlined in red):</source>
        <translation>
            <numerusform>Model ma %n problem (obrysowany na czerwono):</numerusform>
            <numerusform>Model ma %n problemy (obrysowane na czerwono):</numerusform>
            <numerusform>Model ma %n problemów (obrysowanych na czerwono):</numerusform>
        </translation>
    </message>
    <message>
        <location line="+29"/>
        <source>The study&apos;s report has no feature “%1”</source>
        <translation>Raport badania nie ma elementu „%1”</translation>
    </message>
    <message numerus="yes">
        <location line="+51"/>
        <source>What the %1 calls the dimension (%n feature(s) offered); empty: its id</source>
        <translation>
            <numerusform>Jak %1 nazywa wymiar (%n element do wyboru); puste: jego identyfikator</numerusform>
            <numerusform>Jak %1 nazywa wymiar (%n elementy do wyboru); puste: jego identyfikator</numerusform>
            <numerusform>Jak %1 nazywa wymiar (%n elementów do wyboru); puste: jego identyfikator</numerusform>
        </translation>
    </message>
    <message>
        <location line="+54"/>
        <location line="+20"/>
        <source>Add node</source>
        <translation>Dodaj węzeł</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>&amp;Level:</source>
        <translation>&amp;Poziom:</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+64"/>
        <source>&amp;Id:</source>
        <translation>&amp;Identyfikator:</translation>
    </message>
    <message>
        <location line="-59"/>
        <location line="+68"/>
        <source>The id &quot;%1&quot; is empty or already used by another node.</source>
        <translation>Identyfikator „%1” jest pusty lub używany już przez inny węzeł.</translation>
    </message>
    <message>
        <location line="-60"/>
        <location line="+30"/>
        <source>Add arc</source>
        <translation>Dodaj łuk</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>+1 (the target moves with the source)</source>
        <translation>+1 (cel porusza się zgodnie ze źródłem)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>−1 (the target moves against the source)</source>
        <translation>−1 (cel porusza się przeciwnie do źródła)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;From:</source>
        <translation>&amp;Od:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;To:</source>
        <translation>&amp;Do:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Weight:</source>
        <translation>&amp;Waga:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The arc %1 → %2 exists already or an end is empty.</source>
        <translation>Łuk %1 → %2 już istnieje lub jeden z końców jest pusty.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Edit %1</source>
        <translation>Edycja %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Kind:</source>
        <translation>&amp;Rodzaj:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Edit node</source>
        <translation>Edycja węzła</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Export graph as SVG</source>
        <translation>Eksport grafu jako SVG</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Export graph as PNG</source>
        <translation>Eksport grafu jako PNG</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SVG drawings (*.svg)</source>
        <translation>Rysunki SVG (*.svg)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PNG images (*.png)</source>
        <translation>Obrazy PNG (*.png)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot export the graph</source>
        <translation>Nie można wyeksportować grafu</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupGraphView</name>
    <message>
        <location filename="../widgets/setup/setupgraphview.cpp" line="+311"/>
        <source>Unknown nodes</source>
        <translation>Nieznane węzły</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&apos;%1&apos; is not a node of the model (an arc names it)</source>
        <translation>„%1” nie jest węzłem modelu (wskazuje go łuk)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 → %2, weight %3</source>
        <translation>%1 → %2, waga %3</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>weight −1: the target moves against the source</source>
        <translation>waga −1: cel porusza się przeciwnie do źródła</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>weight +1: the target moves with the source</source>
        <translation>waga +1: cel porusza się zgodnie ze źródłem</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>red outline: a problem of the model (see its tooltip)</source>
        <translation>czerwony obrys: problem modelu (patrz podpowiedź)</translation>
    </message>
    <message>
        <location line="+143"/>
        <location line="+22"/>
        <location line="+18"/>
        <source>Cannot write %1: %2</source>
        <translation>Nie można zapisać %1: %2</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>Relation graph of %1</source>
        <translation>Graf relacji: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setup model: machine points, work offsets, tools, features, dimensions</source>
        <translation>Model ustawczy: punkty maszyny, przesunięcia punktu zerowego, narzędzia, elementy geometryczne, wymiary</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write %1: the SVG generator did not start</source>
        <translation>Nie można zapisać %1: generator SVG nie uruchomił się</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupMargins</name>
    <message>
        <location filename="../widgets/setup/setupmargins.cpp" line="+81"/>
        <source>tolerance zone</source>
        <translation>pole tolerancji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>before: deviation and margin to the nearer limit</source>
        <translation>przed: odchyłka i zapas do bliższej granicy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>after correction</source>
        <translation>po korekcji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of tolerance</source>
        <translation>poza tolerancją</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>deviation from nominal (mm)</source>
        <translation>odchyłka od wartości nominalnej (mm)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>margin (mm)</source>
        <translation>zapas (mm)</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupMarginsWidget</name>
    <message>
        <location line="+54"/>
        <source>Run a method to see the margins before and after correction.</source>
        <translation>Uruchom metodę, aby zobaczyć zapasy przed i po korekcji.</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupModelEditor</name>
    <message>
        <location filename="../widgets/setup/setupmodeleditor.cpp" line="+67"/>
        <source>Machine points (M)</source>
        <translation>Punkty maszyny (M)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Work offsets (W)</source>
        <translation>Przesunięcia punktu zerowego (W)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tools (T)</source>
        <translation>Narzędzia (T)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Features (F)</source>
        <translation>Elementy geometryczne (F)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Dimensions (D)</source>
        <translation>Wymiary (D)</translation>
    </message>
    <message>
        <location line="+160"/>
        <source>Add %1</source>
        <translation>Dodanie %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Remove %1</source>
        <translation>Usunięcie %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Rename %1 to %2</source>
        <translation>Zmiana nazwy %1 na %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Change the kind of %1</source>
        <translation>Zmiana rodzaju %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Add arc %1 → %2</source>
        <translation>Dodanie łuku %1 → %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Remove arc %1 → %2</source>
        <translation>Usunięcie łuku %1 → %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Set weight of %1 → %2 to %3</source>
        <translation>Ustawienie wagi %1 → %2 na %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Edit tolerance of %1</source>
        <translation>Edycja tolerancji %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Clear the report feature of %1</source>
        <translation>Usuń element raportu wymiaru %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Map %1 to the report feature %2</source>
        <translation>Przypisz %1 do elementu raportu %2</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupPage</name>
    <message>
        <location filename="../app/gui/setuppage.cpp" line="+152"/>
        <source>&amp;Save model</source>
        <translation>Zapi&amp;sz model</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;vert</source>
        <translation>P&amp;rzywróć</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Run</source>
        <translation>&amp;Uruchom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;lear chart</source>
        <translation>Wyczyść wy&amp;kres</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Write the edited model to its dataset file</source>
        <translation>Zapisz edytowany model do pliku jego zbioru danych</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read the model file again (one undo step: Ctrl+Z brings the edits back)</source>
        <translation>Wczytaj ponownie plik modelu (jeden krok cofania: Ctrl+Z przywraca zmiany)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cannot save the setup model</source>
        <translation>Nie można zapisać modelu ustawczego</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot revert the setup model</source>
        <translation>Nie można przywrócić modelu ustawczego</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>exact: the LP/MILP optimum (GLPK); the metaheuristics with the paper&apos;s settings</source>
        <translation>dokładna: optimum LP/MILP (GLPK); metaheurystyki z ustawieniami z publikacji</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> solutions</source>
        <translation> rozwiązań</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Solutions a metaheuristic evaluates (the paper: 5000)</source>
        <translation>Liczba rozwiązań ocenianych przez metaheurystykę (publikacja: 5000)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Seed of the metaheuristic: the same seed gives the same run</source>
        <translation>Ziarno metaheurystyki: to samo ziarno daje ten sam przebieg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the method (Ctrl+R)</source>
        <translation>Uruchom metodę (Ctrl+R)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Method:</source>
        <translation>&amp;Metoda:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Budget:</source>
        <translation>&amp;Budżet:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>S&amp;eed:</source>
        <translation>Zi&amp;arno:</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>&amp;Graph</source>
        <translation>&amp;Graf</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R&amp;un</source>
        <translation>Pr&amp;zebieg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Res&amp;ults</source>
        <translation>W&amp;yniki</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Va&amp;lidation</source>
        <translation>Wa&amp;lidacja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run</source>
        <translation>Uruchom</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Change the setup method</source>
        <translation>Zmiana metody ustawienia</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Change the setup budget</source>
        <translation>Zmiana budżetu ustawienia</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Change the setup seed</source>
        <translation>Zmiana ziarna ustawienia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From &amp;report…</source>
        <translation>Z &amp;raportu…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Create the setup model from a CMM report of the project, or add the report&apos;s features the model lacks</source>
        <translation>Utwórz model ustawienia z raportu CMM projektu albo dodaj elementy raportu, których brakuje w modelu</translation>
    </message>
    <message>
        <location line="+112"/>
        <source>The applied effects cannot be used: %1</source>
        <translation>Nie można użyć zastosowanych efektów: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>This project has no setup model and no CMM report. Import a CMM report (File › Import), then create the model from it with “From report…”.</source>
        <translation>Ten projekt nie ma modelu ustawienia ani raportu CMM. Zaimportuj raport CMM (Plik › Importuj), a potem utwórz z niego model przyciskiem „Z raportu…”.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This project has no setup model yet. Create it from the CMM report “%1” with “From report…” (or the report&apos;s context menu in the project navigator).</source>
        <translation>Ten projekt nie ma jeszcze modelu ustawienia. Utwórz go z raportu CMM „%1” przyciskiem „Z raportu…” (albo z menu kontekstowego raportu w nawigatorze projektu).</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>The project has no CMM report: import one first (File › Import).</source>
        <translation>Projekt nie ma raportu CMM: najpierw go zaimportuj (Plik › Importuj).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>“%1” is not a CMM report (OGP, PC-DMIS, DMIS, DFQ, Calypso, QIF) of the project.</source>
        <translation>„%1” nie jest raportem CMM (OGP, PC-DMIS, DMIS, DFQ, Calypso, QIF) projektu.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>“%1” is not a dataset of the project.</source>
        <translation>„%1” nie jest zbiorem danych projektu.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The project has no setup model to add features to.</source>
        <translation>Projekt nie ma modelu ustawienia, do którego można dodać elementy.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save or revert the edits of the setup model before you add the features of another report.</source>
        <translation>Zapisz lub cofnij zmiany modelu ustawienia, zanim dodasz elementy innego raportu.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Use the report %1 for the setup study</source>
        <translation>Użyj raportu %1 w badaniu ustawienia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add report features to the setup model</source>
        <translation>Dodaj elementy raportu do modelu ustawienia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The model reads every checked characteristic already.</source>
        <translation>Model odczytuje już każdą zaznaczoną charakterystykę.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot create the folder %1 for the setup model.</source>
        <translation>Nie można utworzyć folderu %1 na model ustawienia.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Setup model made from the CMM report %1</source>
        <translation>Model ustawienia utworzony z raportu CMM %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Create setup model %1 from report %2</source>
        <translation>Utwórz model ustawienia %1 z raportu %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cannot read the CMM report</source>
        <translation>Nie można odczytać raportu CMM</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>This project has no CMM report for the setup study (a dataset of kind &quot;cmm_report&quot;).</source>
        <translation>Ten projekt nie ma raportu WMP dla studium ustawienia (zbiór danych rodzaju „cmm_report”).</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The project has no setup model dataset to revert to.</source>
        <translation>Projekt nie ma zbioru danych modelu ustawczego, do którego można wrócić.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Revert the setup model</source>
        <translation>Przywróć model ustawczy</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Recover autosaved model edits</source>
        <translation>Przywróć automatycznie zapisane zmiany modelu</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+468"/>
        <source>No result for this model yet: choose a method and press Run (Ctrl+R).</source>
        <translation>Brak jeszcze wyniku dla tego modelu: wybierz metodę i naciśnij Uruchom (Ctrl+R).</translation>
    </message>
    <message numerus="yes">
        <location line="-458"/>
        <source>The edited model has %n problem(s), the first: %1</source>
        <translation>
            <numerusform>Edytowany model ma %n problem: %1</numerusform>
            <numerusform>Edytowany model ma %n problemy, pierwszy: %1</numerusform>
            <numerusform>Edytowany model ma %n problemów, pierwszy: %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+26"/>
        <source>studies.setup.budget: must be a whole number of solutions</source>
        <translation>studies.setup.budget: musi być całkowitą liczbą rozwiązań</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>studies.setup.budget: more solutions than the page can run (at most %1)</source>
        <translation>studies.setup.budget: więcej rozwiązań, niż strona może uruchomić (najwyżej %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>studies.setup.seed: larger than the page can use (at most %1)</source>
        <translation>studies.setup.seed: większe, niż strona może użyć (najwyżej %1)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Model “%1” (%2): %3 setup data (%4 work offsets, %5 tools, %6 machine points), %7 features, %8 dimensions, %9 arcs; axis %10, grid %11 mm, bounds [%12, %13] mm.</source>
        <translation>Model „%1” (%2): dane ustawcze: %3 (przesunięcia punktu zerowego: %4, narzędzia: %5, punkty maszyny: %6), elementy geometryczne: %7, wymiary: %8, łuki: %9; oś %10, siatka %11 mm, granice [%12; %13] mm.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Edited, not saved.</source>
        <translation>Edytowano, nie zapisano.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Report “%1”: %2 parts, %3 rows.</source>
        <translation>Raport „%1”: przedmioty: %2, wiersze: %3.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Smallest error budget before correction f1 = %1 mm.</source>
        <translation>Najmniejszy budżet błędu przed korekcją f1 = %1 mm.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>deviations predicted for part %1; residual rms %2 mm (declared model %3 mm)</source>
        <translation>odchyłki przewidywane dla przedmiotu %1; residuum rms %2 mm (zadeklarowany model %3 mm)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>, last part predicted from the others %1 mm (declared %2 mm)</source>
        <translation>, ostatni przedmiot przewidziany z pozostałych %1 mm (zadeklarowany %2 mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Includes applied effects: %1 — %2.</source>
        <translation>Zawiera zastosowane efekty: %1 — %2.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Effects applied on the Diagnosis page belong to the report %1 (the one the diagnosis ran on); this report uses the declared model.</source>
        <translation>Efekty zastosowane na stronie Diagnoza należą do raportu %1 (tego, na którym przeprowadzono diagnozę); ten raport używa zadeklarowanego modelu.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The setup study&apos;s run settings are invalid, nothing is run until they are corrected (choose a value, Undo, or the project file): %1</source>
        <translation>Ustawienia uruchomienia badania ustawień są nieprawidłowe; nic nie zostanie uruchomione, dopóki nie zostaną poprawione (wybierz wartość, Cofnij lub plik projektu): %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The setup study has no model or report to run on.</source>
        <translation>Studium ustawienia nie ma modelu ani raportu do obliczeń.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Not run: %1</source>
        <translation>Nie uruchomiono: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Exact optimum: %1 solver calls in %2 ms.</source>
        <translation>Dokładne optimum: wywołania solvera: %1 w %2 ms.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Running %1…</source>
        <translation>Uruchamianie %1…</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>The run failed: %1</source>
        <translation>Przebieg nie powiódł się: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: f1 %2 mm after %3 solutions in %4 ms</source>
        <translation>%1: f1 %2 mm po %3 rozwiązaniach w %4 ms</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>, gap to the exact optimum %1 mm</source>
        <translation>, różnica do dokładnego optimum %1 mm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — cancelled.</source>
        <translation> — anulowano.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The project has no setup model dataset to save to.</source>
        <translation>Projekt nie ma zbioru danych modelu ustawczego, do którego można zapisać.</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>The model has %n problem(s); fix them before saving. The first: %1</source>
        <translation>
            <numerusform>Model ma %n problem; usuń go przed zapisaniem: %1</numerusform>
            <numerusform>Model ma %n problemy; usuń je przed zapisaniem. Pierwszy: %1</numerusform>
            <numerusform>Model ma %n problemów; usuń je przed zapisaniem. Pierwszy: %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The model was saved, but the CMM report does not match it any more (the runs use the report as read against the previous model): %1</source>
        <translation>Model zapisano, ale raport WMP już do niego nie pasuje (przebiegi używają raportu wczytanego względem poprzedniego modelu): %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>CRIPSO and PSO, seed 1, %1 solutions each, against the exact optimum.</source>
        <translation>CRIPSO i PSO, ziarno 1, po %1 rozwiązań, w porównaniu z dokładnym optimum.</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>The stored result (computed %1) is out of date: the run settings, the model or the applied effects changed since. Not run with these yet: press Run (Ctrl+R).</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: ustawienia uruchomienia, model lub zastosowane efekty zmieniły się od tego czasu. Jeszcze nie uruchomiono z nimi: naciśnij Uruchom (Ctrl+R).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the CMM report changed since. Press Run (Ctrl+R) to correct the setup for the report as it is now.</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: raport WMP zmienił się od tego czasu. Naciśnij Uruchom (Ctrl+R), aby skorygować ustawienie dla raportu w obecnej postaci.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the CMM report cannot be read.</source>
        <translation>Nie można sprawdzić zapisanego wyniku (obliczonego %1): nie można odczytać raportu WMP.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>From the saved project (computed %1 with these settings, this model and this report): %2: f1 %3 → %4 mm, |x| = f2 %5 mm, f %6; corrections (mm) %7; %8 of %9 parts in tolerance before, %10 after. Press Run (Ctrl+R) to see the tables and exports.</source>
        <translation>Z zapisanego projektu (obliczono %1 z tymi ustawieniami, tym modelem i tym raportem): %2: f1 %3 → %4 mm, |x| = f2 %5 mm, f %6; korekty (mm) %7; %8 z %9 części w tolerancji przed, %10 po. Naciśnij Uruchom (Ctrl+R), aby zobaczyć tabele i eksporty.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Nothing is run while the setup study&apos;s run settings are invalid: %1</source>
        <translation>Nic nie zostanie uruchomione, dopóki ustawienia uruchomienia badania ustawień są nieprawidłowe: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupResultsView</name>
    <message>
        <location filename="../widgets/setup/setupresultsview.cpp" line="+37"/>
        <source>machine point</source>
        <translation>punkt maszyny</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work offset</source>
        <translation>przesunięcie punktu zerowego</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>tool length</source>
        <translation>długość narzędzia</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Export Q-DAS &amp;DFQ…</source>
        <translation>Eksportuj Q-DAS &amp;DFQ…</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Setup datum</source>
        <translation>Dana ustawcza</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>Rodzaj</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Register</source>
        <translation>Rejestr</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Correction (mm)</source>
        <translation>Korekcja (mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Increment to add to the register along the model&apos;s axis (see the export headers)</source>
        <translation>Przyrost do dodania do rejestru wzdłuż osi modelu (patrz nagłówki eksportu)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Export the corrections:</source>
        <translation>Eksport korekcji:</translation>
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
        <translation>Aktualizuj &amp;tabelę HEIDENHAIN…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Add the corrections to the control&apos;s current preset table (.PR) or tool table (.T), saved from the control, and write the result to a new file for import; the rows are the registers of the model</source>
        <translation>Dodaj korekcje do bieżącej tabeli punktów bazowych (.PR) lub tabeli narzędzi (.T) sterowania, zapisanej ze sterowania, i zapisz wynik do nowego pliku do importu; wiersze to rejestry modelu</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Tool re&amp;gister:</source>
        <translation>Re&amp;jestr narzędzia:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>wear (DL)</source>
        <translation>zużycie (DL)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>geometry (L)</source>
        <translation>geometria (L)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The register the tool-length corrections go to in every export: the wear (DL, Fanuc H wear) or the geometry (L)</source>
        <translation>Rejestr, do którego trafiają korekcje długości narzędzia w każdym eksporcie: zużycie (DL, Fanuc zużycie H) lub geometria (L)</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+252"/>
        <source>There is no measurement report to export</source>
        <translation>Brak raportu pomiarowego do eksportu</translation>
    </message>
    <message>
        <location line="-222"/>
        <source>No result yet: choose a method and press Run (Ctrl+R).</source>
        <translation>Brak jeszcze wyniku: wybierz metodę i naciśnij Uruchom (Ctrl+R).</translation>
    </message>
    <message numerus="yes">
        <location line="+44"/>
        <source>%n LP / MILP solver call(s)</source>
        <translation>
            <numerusform>%n wywołanie solvera LP / MILP</numerusform>
            <numerusform>%n wywołania solvera LP / MILP</numerusform>
            <numerusform>%n wywołań solvera LP / MILP</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n solution(s) evaluated</source>
        <translation>
            <numerusform>oceniono %n rozwiązanie</numerusform>
            <numerusform>oceniono %n rozwiązania</numerusform>
            <numerusform>oceniono %n rozwiązań</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: f1 %2 → %3 mm (bonus %4 mm), |x| = f2 %5 mm, f %6; %7 in %8 ms.</source>
        <translation>%1: f1 %2 → %3 mm (premia %4 mm), |x| = f2 %5 mm, f %6; %7 w %8 ms.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>f1 proven optimal on the grid</source>
        <translation>f1 udowodnione jako optymalne na siatce</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f1 NOT proven optimal</source>
        <translation>f1 NIE udowodnione jako optymalne</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>|x| proven minimal.</source>
        <translation>|x| udowodnione jako minimalne.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>|x| not proven minimal.</source>
        <translation>|x| nie udowodnione jako minimalne.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gap to the exact optimum: f1 %1 mm, f2 %2 mm.</source>
        <translation>Różnica do dokładnego optimum: f1 %1 mm, f2 %2 mm.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(cancelled: best so far)</source>
        <translation>(anulowano: najlepsze dotąd)</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Parts of the report in tolerance: %1 of %2 before, %3 of %2 after the correction; parts rescued: %4.</source>
        <translation>Przedmioty z raportu w tolerancji: %1 z %2 przed, %3 z %2 po korekcji; uratowane przedmioty: %4.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Parts that would leave the tolerance: %1.</source>
        <translation>Przedmioty, które wypadłyby z tolerancji: %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+40"/>
        <source>There are no corrections to export yet.</source>
        <translation>Nie ma jeszcze korekcji do wyeksportowania.</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>Export corrections</source>
        <translation>Eksport korekcji</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot export the corrections</source>
        <translation>Nie można wyeksportować korekcji</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The updated table must go to a new file: %1 is the table read from the control.</source>
        <translation>Zaktualizowana tabela musi trafić do nowego pliku: %1 to tabela odczytana ze sterowania.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The control&apos;s current table (saved from the control)</source>
        <translation>Bieżąca tabela sterowania (zapisana ze sterowania)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HEIDENHAIN preset and tool tables (*.PR *.pr *.T *.t);;All files (*)</source>
        <translation>Tabele punktów bazowych i narzędzi HEIDENHAIN (*.PR *.pr *.T *.t);;Wszystkie pliki (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Write the updated table to</source>
        <translation>Zapisz zaktualizowaną tabelę do</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot update the HEIDENHAIN table</source>
        <translation>Nie można zaktualizować tabeli HEIDENHAIN</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 written to %2. Cells updated: %3.</source>
        <translation>%1 zapisano do %2. Zaktualizowane komórki: %3.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none</source>
        <translation>brak</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not in this table: %1.</source>
        <translation>Nie w tej tabeli: %1.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import it with no NC program running, then activate the preset again or call the tool again.</source>
        <translation>Zaimportuj ją, gdy żaden program NC nie działa, a następnie ponownie aktywuj punkt bazowy lub ponownie wywołaj narzędzie.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HEIDENHAIN table updated</source>
        <translation>Tabela HEIDENHAIN zaktualizowana</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Write the measured features of the report as a Q-DAS DFQ file (one characteristic per measured dimension)</source>
        <translation>Zapisz zmierzone cechy raportu jako plik Q-DAS DFQ (jedna charakterystyka na każdy zmierzony wymiar)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>There is no measurement report to export.</source>
        <translation>Brak raportu pomiarowego do eksportu.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export Q-DAS DFQ</source>
        <translation>Eksport Q-DAS DFQ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Q-DAS DFQ files (*.dfq);;All files (*)</source>
        <translation>Pliki Q-DAS DFQ (*.dfq);;Wszystkie pliki (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot export the DFQ file</source>
        <translation>Nie można wyeksportować pliku DFQ</translation>
    </message>
</context>
<context>
    <name>metrofit::SetupValidationView</name>
    <message>
        <location filename="../widgets/setup/setupvalidationview.cpp" line="+78"/>
        <source>Simulated measurement sets N (the paper: 100)</source>
        <translation>Symulowane zestawy pomiarów N (publikacja: 100)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Trials M of every method on every set (the paper: 10)</source>
        <translation>Próby M każdej metody na każdym zestawie (publikacja: 10)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> solutions</source>
        <translation> rozwiązań</translation>
    </message>
    <message>
        <location line="+7"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Weight of the setup-data errors, Eq. 12: E = w1 (1 − 2r)</source>
        <translation>Waga błędów danych ustawczych, równ. 12: E = w1 (1 − 2r)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Weight of the random errors, Eq. 13: E = w2 (1 − 2r)</source>
        <translation>Waga błędów losowych, równ. 13: E = w2 (1 − 2r)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Run &amp;validation</source>
        <translation>Uruchom walidac&amp;ję</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <location line="-49"/>
        <source>The paper&apos;s statistical validation: simulated measurement sets with setup-data and random errors (Eq. 12–13), each corrected by the exact method and by M trials of the chosen metaheuristics; the sets sorted by their budget before correction (Fig. 18).</source>
        <translation>Walidacja statystyczna z publikacji: symulowane zestawy pomiarów z błędami danych ustawczych i losowymi (równ. 12–13), każdy korygowany metodą dokładną i M próbami wybranych metaheurystyk; zestawy posortowane wg budżetu przed korekcją (rys. 18).</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>Measurement sets N:</source>
        <translation>Zestawy pomiarów N:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trials per set M:</source>
        <translation>Próby na zestaw M:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Budget per trial:</source>
        <translation>Budżet na próbę:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>w1 (setup data):</source>
        <translation>w1 (dane ustawcze):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>w2 (random):</source>
        <translation>w2 (losowe):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Seed:</source>
        <translation>Ziarno:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Methods:</source>
        <translation>Metody:</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>Choose at least one method.</source>
        <translation>Wybierz co najmniej jedną metodę.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Running %1 sets x %2 trials…</source>
        <translation>Obliczanie: %1 zestawów x %2 prób…</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>The validation failed: %1</source>
        <translation>Walidacja nie powiodła się: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 sets%2: f1 before correction from %3 to %4 mm.</source>
        <translation>Zestawy: %1%2: f1 przed korekcją od %3 do %4 mm.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (cancelled)</source>
        <translation> (anulowano)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The paper&apos;s range %1 to %2 mm is consistent with the simulator (its minimum lies in %3 to %4 mm, its maximum in %5 to %6 mm over 100 sets, 98 % bands).</source>
        <translation>Zakres z artykułu, od %1 do %2 mm, jest zgodny z symulatorem (jego minimum leży w przedziale od %3 do %4 mm, maksimum od %5 do %6 mm dla 100 zestawów, pasma 98 %).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NOT consistent: the paper&apos;s range %1 to %2 mm lies outside the simulator&apos;s bands (minimum %3 to %4 mm, maximum %5 to %6 mm over 100 sets, 98 %).</source>
        <translation>NIEZGODNY: zakres z artykułu, od %1 do %2 mm, leży poza pasmami symulatora (minimum od %3 do %4 mm, maksimum od %5 do %6 mm dla 100 zestawów, 98 %).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The paper&apos;s range (%1 to %2 mm) is for w1 = 0.03 and w2 = 0.02 mm: not compared.</source>
        <translation>Zakres z artykułu (od %1 do %2 mm) dotyczy w1 = 0,03 i w2 = 0,02 mm: nie porównano.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: mean gap to the exact f1 %2 mm; %3 of %4 trials within one grid step.</source>
        <translation>%1: średnia różnica do dokładnego f1 %2 mm; %3 z %4 prób w granicach jednego kroku siatki.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Share of the setup data in the dimension error, estimated from the sets: %1 % of the weights (configured %2 %), %3 % of the variance.</source>
        <translation>Udział danych ustawczych w błędzie wymiaru, oszacowany z zestawów: %1 % wag (ustawiono %2 %), %3 % wariancji.</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>In the project&apos;s measurements (%n part(s)): %1 % of the weights, %2 % of the variance.</source>
        <translation>
            <numerusform>W pomiarach projektu (%n przedmiot): %1 % wag, %2 % wariancji.</numerusform>
            <numerusform>W pomiarach projektu (%n przedmioty): %1 % wag, %2 % wariancji.</numerusform>
            <numerusform>W pomiarach projektu (%n przedmiotów): %1 % wag, %2 % wariancji.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The setup share of the measurements cannot be estimated: %1</source>
        <translation>Nie można oszacować udziału danych ustawczych w pomiarach: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::SpcView</name>
    <message>
        <location filename="../widgets/kinematics/kinematicsviews.cpp" line="+135"/>
        <source>index</source>
        <translation>wskaźnik</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>value</source>
        <translation>wartość</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>No SPC series yet.</source>
        <translation>Brak jeszcze serii SPC.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Histogram of %1 (%2 values)</source>
        <translation>Histogram %1 (wartości: %2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>feature</source>
        <translation>cecha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroups × size</source>
        <translation>podgrupy × liczność</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> (%1 left out)</source>
        <translation> (pominięto %1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>in control</source>
        <translation>pod kontrolą</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>yes</source>
        <translation>tak</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no: %1 X-bar, %2 R points beyond limits</source>
        <translation>nie: punkty poza granicami: %1 X-średnie, %2 R</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Nelson rules</source>
        <translation>Reguły Nelsona</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A2 / D3 / D4</source>
        <translation>A2 / D3 / D4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>X-bar CL / UCL / LCL</source>
        <translation>X-średnie CL / UCL / LCL</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>R CL / UCL / LCL</source>
        <translation>R CL / UCL / LCL</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>σ within (R̄/d2)</source>
        <translation>σ wewnątrz (R̄/d2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>LSL / USL</source>
        <translation>LSL / USL</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cp (Eq. 16)</source>
        <translation>Cp (równ. 16)</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <source>— (no limits)</source>
        <translation>— (brak granic)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cpk</source>
        <translation>Cpk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>natural tolerance (Eq. 17)</source>
        <translation>tolerancja naturalna (równ. 17)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+5"/>
        <source>systematic error (Eq. 20)</source>
        <translation>błąd systematyczny (równ. 20)</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>%1%2 ± %3 (%4)</source>
        <translation>%1%2 ± %3 (%4)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>significant</source>
        <translation>istotny</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not significant</source>
        <translation>nieistotny</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>— (no nominal)</source>
        <translation>— (brak wartości nominalnej)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>regression offset angle</source>
        <translation>kąt przesunięcia regresji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1° (slope %2%3 per sample, r² %4)</source>
        <translation>%1° (nachylenie %2%3 na próbkę, r² %4)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>compensation</source>
        <translation>kompensacja</translation>
    </message>
</context>
<context>
    <name>metrofit::StoredResult</name>
    <message>
        <location filename="../widgets/document/storedresulttext.cpp" line="+11"/>
        <source>at an unknown time</source>
        <translation>w nieznanym czasie</translation>
    </message>
</context>
<context>
    <name>metrofit::StudyActions</name>
    <message>
        <location filename="../app/gui/studyactions.cpp" line="+52"/>
        <source>&amp;Run</source>
        <translation>&amp;Uruchom</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Run the study</source>
        <translation>&amp;Uruchom studium</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Runs the method of the page shown (its Run button, Ctrl+R)</source>
        <translation>Uruchamia metodę wyświetlanej strony (jej przycisk Uruchom, Ctrl+R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Cancel the run</source>
        <translation>&amp;Anuluj obliczenia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stops the running method of the page shown</source>
        <translation>Zatrzymuje działającą metodę wyświetlanej strony</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Nothing to run on this page</source>
        <translation>Na tej stronie nie ma nic do uruchomienia</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Nothing is running</source>
        <translation>Nic nie jest uruchomione</translation>
    </message>
</context>
<context>
    <name>metrofit::TableCopy</name>
    <message>
        <location filename="../widgets/common/tablecopy.cpp" line="+88"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopiuj</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Copy the selected cells with their column headers, tab-separated</source>
        <translation>Kopiuj zaznaczone komórki wraz z nagłówkami kolumn, rozdzielone tabulatorami</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Select &amp;all</source>
        <translation>Zaznacz &amp;wszystko</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalCharts</name>
    <message>
        <location filename="../widgets/thermal/thermalcharts.cpp" line="+55"/>
        <source>temperature</source>
        <translation>temperatura</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacement</source>
        <translation>przemieszczenie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>strain</source>
        <translation>odkształcenie</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+17"/>
        <source>speed</source>
        <translation>prędkość</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>value</source>
        <translation>wartość</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>temperatures</source>
        <translation>temperatury</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>displacements</source>
        <translation>przemieszczenia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>strains</source>
        <translation>odkształcenia</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>other channels</source>
        <translation>inne kanały</translation>
    </message>
    <message>
        <location line="+92"/>
        <location line="+113"/>
        <source>feed speed</source>
        <translation>prędkość posuwu</translation>
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
        <translation>czas (h)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time (min)</source>
        <translation>czas (min)</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>heating</source>
        <translation>nagrzewanie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cooling</source>
        <translation>chłodzenie</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalHysteresisView</name>
    <message>
        <location filename="../widgets/thermal/thermalhysteresisview.cpp" line="+187"/>
        <source>loop area in %1 × %2</source>
        <translation>pole pętli w %1 × %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the sensor lags the displacement</source>
        <translation>czujnik opóźnia się względem przemieszczenia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the displacement lags the sensor</source>
        <translation>przemieszczenie opóźnia się względem czujnika</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Sensor plotted against the displacement, or all sensors side by side</source>
        <translation>Czujnik względem przemieszczenia lub wszystkie czujniki obok siebie</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>sensor</source>
        <translation>czujnik</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>loop area</source>
        <translation>pole pętli</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>loop / ranges</source>
        <translation>pętla / rozstępy</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lag τ (min)</source>
        <translation>opóźnienie τ (min)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R² lag</source>
        <translation>R² opóźnienia</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>R² static</source>
        <translation>R² statyczny</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Area enclosed by the trajectory (shoelace formula), sensor unit × displacement unit</source>
        <translation>Pole objęte trajektorią (wzór Gaussa, sznurowadłowy), jednostka czujnika × jednostka przemieszczenia</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Loop area divided by the product of the two ranges: 0 for a line, 0.785 for a circle</source>
        <translation>Pole pętli podzielone przez iloczyn obu rozstępów: 0 dla linii, 0.785 dla okręgu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Time constant of a first-order lag between sensor and displacement; &gt; 0: the sensor lags</source>
        <translation>Stała czasowa członu inercyjnego pierwszego rzędu między czujnikiem a przemieszczeniem; &gt; 0: czujnik się opóźnia</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>&amp;Sensor:</source>
        <translation>Cz&amp;ujnik:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Loop area and lag per sensor</source>
        <translation>Pole pętli i opóźnienie dla każdego czujnika</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Analysing the hysteresis of %1…</source>
        <translation>Analiza histerezy %1…</translation>
    </message>
    <message>
        <location line="-179"/>
        <source>All sensors</source>
        <translation>Wszystkie czujniki</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No hysteresis analysis for this log:
%1</source>
        <translation>Brak analizy histerezy dla tego rejestru:
%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Target %1: %2 heating rows, %3 cooling rows (the target&apos;s change grows or shrinks).</source>
        <translation>Wielkość docelowa %1: wiersze nagrzewania: %2, wiersze chłodzenia: %3 (zmiana wielkości docelowej rośnie lub maleje).</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalModelCharts</name>
    <message>
        <location filename="../widgets/thermal/thermalmodelcharts.cpp" line="+70"/>
        <source>time (h)</source>
        <translation>czas (h)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>time (min)</source>
        <translation>czas (min)</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>held out</source>
        <translation>dane testowe</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>fit | held-out boundary</source>
        <translation>granica dopas./test</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1: not fitted</source>
        <translation>%1: nie dopasowano</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>%1: lag %2 min</source>
        <translation>%1: opóźnienie %2 min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 against %2: lag %3 min, loop %4</source>
        <translation>%1 względem %2: opóźnienie %3 min, pętla %4</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>heating</source>
        <translation>nagrzewanie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cooling</source>
        <translation>chłodzenie</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>measured</source>
        <translation>zmierzony</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+47"/>
        <source>%1 (off scale)</source>
        <translation>%1 (poza skalą)</translation>
    </message>
    <message>
        <location line="-23"/>
        <source>residual</source>
        <translation>reszta</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>measured (combined test)</source>
        <translation>zmierzony (test łączony)</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>module %1</source>
        <translation>moduł %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>modules, summed</source>
        <translation>moduły, zsumowane</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>PSO iteration</source>
        <translation>iteracja PSO</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>best fitness</source>
        <translation>najlepsze przystosowanie</translation>
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
        <translation>używane przez %1 (błąd danych testowych %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not used by %1 (held-out error would rise: %2)</source>
        <translation>nieużywane przez %1 (błąd danych testowych wzrósłby: %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not used by %1 (held-out error would not fall: %2)</source>
        <translation>nieużywane przez %1 (błąd danych testowych nie zmalałby: %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Applied effects %1: %2.</source>
        <translation>Zastosowane efekty %1: %2.</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>Applied effects %1: Train (Ctrl+R) fits each model with and without them and keeps the lower held-out error.</source>
        <translation>Zastosowane efekty %1: Trenuj (Ctrl+R) dopasowuje każdy model z nimi i bez nich i zachowuje mniejszy błąd danych testowych.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Effects added with Apply on the Diagnosis page (lagged inputs, extra input columns, a drift term, generic effects as the curve, step or levels the diagnosis fitted). Each model is fitted with the declared inputs and with the effects (same seed) and keeps the variant with the lower held-out error: an effect never makes a model worse on the held-out rows. Undo the Apply to fit the declared model only.</source>
        <translation>Efekty dodane przyciskiem „Zastosuj do modelu” na stronie Diagnoza (opóźnione wejścia, dodatkowe kolumny wejściowe, składnik dryftu, efekty ogólne jako krzywa, skok lub poziomy dopasowane przez diagnozę). Każdy model jest dopasowywany z zadeklarowanymi wejściami oraz z efektami (to samo ziarno) i zachowuje wariant o mniejszym błędzie danych testowych: efekt nigdy nie pogarsza modelu na wierszach testowych. Cofnij zastosowanie, aby dopasować tylko zadeklarowany model.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Applied effects cannot be used: %1</source>
        <translation>Nie można użyć zastosowanych efektów: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>fitness</source>
        <translation>fitness</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Best Eq. 2.9 fitness (sum of squared residuals%1) per PSO iteration</source>
        <translation>Najlepsze przystosowanie wg równ. 2.9 (suma kwadratów residuów%1) w każdej iteracji PSO</translation>
    </message>
    <message>
        <location line="+39"/>
        <location line="+133"/>
        <source>not fitted: %1</source>
        <translation>nie dopasowano: %1</translation>
    </message>
    <message>
        <location line="-123"/>
        <source>fit (%1)</source>
        <translation>dopasowanie (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>held out (%1)</source>
        <translation>dane testowe (%1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+120"/>
        <source>diverges</source>
        <translation>rozbieżny</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Least squares gave an unstable GMC(1,N): b1 = %1 ≤ 0; its output grows without bound on the held-out rows</source>
        <translation>Metoda najmniejszych kwadratów dała niestabilny GMC(1,N): b1 = %1 ≤ 0; jego wyjście rośnie bez ograniczeń na danych testowych</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+130"/>
        <location line="+151"/>
        <source>model</source>
        <translation>model</translation>
    </message>
    <message>
        <location line="-281"/>
        <location line="+281"/>
        <source>rows</source>
        <translation>wiersze</translation>
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
        <translation>pasmo</translation>
    </message>
    <message>
        <location line="-278"/>
        <location line="+278"/>
        <source>verdict</source>
        <translation>ocena</translation>
    </message>
    <message>
        <location line="-270"/>
        <source>%1 not fitted: %2.</source>
        <translation>%1 nie dopasowano: %2.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 %2 s</source>
        <translation>%1 %2 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> (unstable: b1 ≤ 0)</source>
        <translation> (niestabilny: b1 ≤ 0)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Best usable model: %1.</source>
        <translation>Najlepszy użyteczny model: %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No model is usable for compensation: record a longer test or add the inputs the diagnosis finds.</source>
        <translation>Żaden model nie nadaje się do kompensacji: zarejestruj dłuższy test lub dodaj wejścia wskazane przez diagnozę.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 fit rows, %2 held out; %3.</source>
        <translation>wiersze dopasowania: %1, dane testowe: %2; %3.</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>modules, summed (distributed lag)</source>
        <translation>moduły, zsumowane (rozłożone opóźnienie)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 (inputs %2) contributes up to %3 %4</source>
        <translation>%1 (wejścia %2) wnosi do %3 %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Module by module, each identified on its own test: %1.</source>
        <translation>Moduł po module, każdy zidentyfikowany na własnym teście: %1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Module by module: not identified (%1).</source>
        <translation>Moduł po module: nie zidentyfikowano (%1).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>error → band (%1)</source>
        <translation>błąd → pasmo (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>less (peak, %)</source>
        <translation>mniej (szczyt, %)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RMSE (%1)</source>
        <translation>RMSE (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>less (RMS, %)</source>
        <translation>mniej (RMS, %)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>not identified</source>
        <translation>nie zidentyfikowano</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Identify again…</source>
        <translation>Zidentyfikuj ponownie…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Identify this module again on another test of its drive (a thermal log of the project); the other modules keep their models</source>
        <translation>Zidentyfikuj ten moduł ponownie na innym teście jego napędu (rejestrze termicznym projektu); pozostałe moduły zachowują swoje modele</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>module</source>
        <translation>moduł</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>identified on</source>
        <translation>zidentyfikowany na</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inputs</source>
        <translation>wejścia</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>contribution (peak)</source>
        <translation>udział (szczyt)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: %p%</source>
        <translation>%1: %p%</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The column the models predict (the thermal error)</source>
        <translation>Kolumna przewidywana przez modele (błąd termiczny)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Sensor columns the models take as inputs</source>
        <translation>Kolumny czujników używane przez modele jako wejścia</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The first fraction of the rows fits the models; the rest is held out</source>
        <translation>Pierwsza część wierszy służy do dopasowania modeli; reszta to dane testowe</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Seed of the PSO swarm and of the MLP&apos;s initial weights (same seed, same result)</source>
        <translation>Ziarno roju PSO i początkowych wag MLP (to samo ziarno, ten sam wynik)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Train</source>
        <translation>T&amp;renuj</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Fit GNNMCI(1,N) (PSO), GMC(1,N) (least squares) and the MLP (Levenberg-Marquardt) (Ctrl+R)</source>
        <translation>Dopasuj GNNMCI(1,N) (PSO), GMC(1,N) (najmniejsze kwadraty) i MLP (Levenberg-Marquardt) (Ctrl+R)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+99"/>
        <source>Cancel</source>
        <translation>Anuluj</translation>
    </message>
    <message>
        <location line="-95"/>
        <source>Stop the training (Esc)</source>
        <translation>Zatrzymaj trenowanie (Esc)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Best fitness of the GNNMCI(1,N) swarm (Eq. 2.9) per PSO iteration</source>
        <translation>Najlepsze przystosowanie roju GNNMCI(1,N) (równ. 2.9) w każdej iteracji PSO</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>T&amp;arget:</source>
        <translation>Wielkość &amp;docelowa:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Train &amp;fraction:</source>
        <translation>Część tre&amp;ningowa:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;eed:</source>
        <translation>Zi&amp;arno:</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Inputs:</source>
        <translation>Wejści&amp;a:</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Correlation coefficient of measured and predicted</source>
        <translation>Współczynnik korelacji wartości zmierzonych i przewidywanych</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Root mean square of the residual, in the target&apos;s unit</source>
        <translation>Średnia kwadratowa residuum, w jednostce wielkości docelowej</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nash-Sutcliffe efficiency coefficient (1: perfect)</source>
        <translation>Współczynnik efektywności Nasha-Sutcliffe&apos;a (1: idealny)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest |residual|, in the target&apos;s unit</source>
        <translation>Największe |residuum|, w jednostce wielkości docelowej</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Usable for compensation when on the held-out rows it does not diverge, E ≥ %1 and R ≥ %2</source>
        <translation>Nadaje się do kompensacji, gdy na odłożonych wierszach nie rozbiega się, E ≥ %1 i R ≥ %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modular models (Section 4.3)</source>
        <translation>Modele modułowe (rozdział 4.3)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Save module models…</source>
        <translation>Zapisz modele modułów…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write each module&apos;s fitted model to a folder as NAME.json (the files of metrofit-cli thermal modular --save-modules)</source>
        <translation>Zapisz dopasowany model każdego modułu w folderze jako NAZWA.json (pliki metrofit-cli thermal modular --save-modules)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop identifying the module; the modules shown stay</source>
        <translation>Zatrzymaj identyfikację modułu; pokazane moduły pozostają</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Performance indices (Table 4)</source>
        <translation>Wskaźniki jakości (tabela 4)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Comparison</source>
        <translation>Porównanie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modular (Z + C → combined)</source>
        <translation>Modułowy (Z + C → łączony)</translation>
    </message>
    <message>
        <location line="+35"/>
        <location line="+118"/>
        <source>Training failed: %1</source>
        <translation>Trenowanie nie powiodło się: %1</translation>
    </message>
    <message>
        <location line="-132"/>
        <source>Training cancelled after %1 PSO iterations; the results shown are the previous ones.</source>
        <translation>Trenowanie anulowano po %1 iteracjach PSO; pokazane wyniki są poprzednie.</translation>
    </message>
    <message>
        <location line="-337"/>
        <source>not fitted</source>
        <translation>nie dopasowano</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;b&gt;Modular case:&lt;/b&gt; GNNMCI(1,N) fitted on the Z and C tests reduces the combined test&apos;s error by %1 (GMC(1,N) %2, MLP %3).</source>
        <translation>&lt;b&gt;Przypadek modułowy:&lt;/b&gt; GNNMCI(1,N) dopasowany na testach Z i C zmniejsza błąd testu łączonego o %1 (GMC(1,N) %2, MLP %3).</translation>
    </message>
    <message>
        <location line="+356"/>
        <source>Settings changed: Train (Ctrl+R) to update the results.</source>
        <translation>Zmieniono ustawienia: Trenuj (Ctrl+R), aby zaktualizować wyniki.</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Not trained yet: Train (Ctrl+R) fits the three models.</source>
        <translation>Jeszcze nie wytrenowano: Trenuj (Ctrl+R) dopasowuje trzy modele.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Applied effects changed: Train (Ctrl+R) to update the results.</source>
        <translation>Zmieniono zastosowane efekty: Trenuj (Ctrl+R), aby zaktualizować wyniki.</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+23"/>
        <source>Choose at least one input.</source>
        <translation>Wybierz co najmniej jedno wejście.</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Training…</source>
        <translation>Trenowanie…</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalPage</name>
    <message>
        <location filename="../app/gui/thermalpage.cpp" line="+128"/>
        <source>Export compensation…</source>
        <translation>Eksportuj kompensację…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write a trained model in a form the machine control runs: an IEC 61131-3 function block, SINUMERIK or Heidenhain data, ISG axis parameters or a table (metrofit-cli thermal export)</source>
        <translation>Zapisz wytrenowany model w postaci, którą wykonuje sterowanie maszyny: blok funkcyjny IEC 61131-3, dane SINUMERIK lub Heidenhain, parametry osi ISG albo tabela (metrofit-cli thermal export)</translation>
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
        <translation>Eksport kompensacji</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>Train the models first (Models tab): the export writes a trained model.</source>
        <translation>Najpierw wytrenuj modele (karta Modele): eksport zapisuje wytrenowany model.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (held-out RMSE %2)</source>
        <translation>%1 (RMSE wierszy testowych %2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No trained model can be exported (a model that takes the applied effects&apos; columns cannot: the control does not have them).</source>
        <translation>Żadnego wytrenowanego modelu nie można wyeksportować (modelu z kolumnami przyjętych efektów nie: sterowanie ich nie ma).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Model:</source>
        <translation>Model:</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Form (st: IEC 61131-3 function block; siemens, heidenhain, isg: the control&apos;s temperature compensation; csv: a table):</source>
        <translation>Postać (st: blok funkcyjny IEC 61131-3; siemens, heidenhain, isg: kompensacja temperaturowa sterowania; csv: tabela):</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot export the compensation: %1</source>
        <translation>Nie można wyeksportować kompensacji: %1</translation>
    </message>
    <message>
        <location line="-91"/>
        <source>T&amp;rend</source>
        <translation>&amp;Trend</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Hysteresis</source>
        <translation>&amp;Histereza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Models</source>
        <translation>&amp;Modele</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temperatures, strains and displacement against time</source>
        <translation>Temperatury, odkształcenia i przemieszczenie w funkcji czasu</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Displacement against each sensor over heating and cooling</source>
        <translation>Przemieszczenie względem każdego czujnika podczas nagrzewania i chłodzenia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNNMCI(1,N), GMC(1,N) and MLP fitted and compared (Table 4)</source>
        <translation>GNNMCI(1,N), GMC(1,N) i MLP dopasowane i porównane (tabela 4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Thermal log:</source>
        <translation>&amp;Rejestr termiczny:</translation>
    </message>
    <message>
        <location line="+127"/>
        <source>The module could not be identified again: %1</source>
        <translation>Nie udało się ponownie zidentyfikować modułu: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cancelled: the modules shown are unchanged.</source>
        <translation>Anulowano: pokazane moduły są bez zmian.</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>studies.thermal.train_fraction: %1 cannot be set on the page (it takes 0.01 to 0.99 in steps of 0.01)</source>
        <translation>studies.thermal.train_fraction: nie można ustawić %1 na stronie (przyjmuje od 0,01 do 0,99 w krokach co 0,01)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>studies.thermal.seed: %1 is larger than the page can use (at most %2)</source>
        <translation>studies.thermal.seed: %1 jest większe, niż strona może użyć (najwyżej %2)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The thermal study&apos;s settings are invalid, nothing is fitted until they are corrected (Undo, or the project file):
%1</source>
        <translation>Ustawienia badania termicznego są nieprawidłowe; nic nie zostanie dopasowane, dopóki nie zostaną poprawione (Cofnij lub plik projektu):
%1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>This project has no thermal log. Add a dataset of kind &quot;thermal_log&quot; to the project file (a time column, sensor columns and the displacement).</source>
        <translation>Ten projekt nie zawiera rejestru termicznego. Dodaj do pliku projektu zbiór danych rodzaju „thermal_log” (kolumna czasu, kolumny czujników i przemieszczenie).</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 rows, %2 channels, %3 h.</source>
        <translation>Wiersze: %1, kanały: %2, czas: %3 h.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Licence: %1.</source>
        <translation>Licencja: %1.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Cannot show this thermal log:
%1</source>
        <translation>Nie można wyświetlić tego rejestru termicznego:
%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Effects applied on the Diagnosis page belong to the log %1 (the one the diagnosis ran on); the models of this log do not include them.</source>
        <translation>Efekty zastosowane na stronie Diagnoza należą do rejestru termicznego %1 (tego, na którym przeprowadzono diagnozę); modele tego rejestru ich nie uwzględniają.</translation>
    </message>
    <message>
        <location line="-185"/>
        <source>Choose the thermal log</source>
        <translation>Wybór rejestru termicznego</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change the thermal target</source>
        <translation>Zmiana wielkości docelowej (termika)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change the thermal inputs</source>
        <translation>Zmiana wejść (termika)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Change the train fraction</source>
        <translation>Zmiana części treningowej</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change the training seed</source>
        <translation>Zmiana ziarna trenowania</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Change the thermal model settings</source>
        <translation>Zmiana ustawień modelu termicznego</translation>
    </message>
    <message>
        <location line="+249"/>
        <source>The stored result (computed %1) is out of date: the model settings changed since. Not trained with these settings yet: Train (Ctrl+R).</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: ustawienia modeli zmieniły się od tego czasu. Jeszcze nie wytrenowano z tymi ustawieniami: Trenuj (Ctrl+R).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) is out of date: the data file changed since. Train (Ctrl+R) to fit the models on the data as it is now.</source>
        <translation>Zapisany wynik (obliczony %1) jest nieaktualny: plik danych zmienił się od tego czasu. Trenuj (Ctrl+R), aby dopasować modele do danych w obecnej postaci.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The stored result (computed %1) cannot be checked: the data file cannot be read.</source>
        <translation>Nie można sprawdzić zapisanego wyniku (obliczonego %1): nie można odczytać pliku danych.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>not fitted</source>
        <translation>niedopasowany</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no model usable for compensation</source>
        <translation>brak modelu użytecznego do kompensacji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>best usable model %1 (held-out RMSE %2)</source>
        <translation>najlepszy użyteczny model %1 (RMSE na odłożonych %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From the saved project, computed %1 with these settings on this data: %2. Held-out RMSE: %3. Train (Ctrl+R) to see the charts.</source>
        <translation>Z zapisanego projektu, obliczono %1 z tymi ustawieniami dla tych danych: %2. RMSE na odłożonych: %3. Trenuj (Ctrl+R), aby zobaczyć wykresy.</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>Fitted on %1 and %2 together, predicting %3 (target %4; inputs %5; seed 1): GNNMCI(1,N) not fitted: %6</source>
        <translation>Dopasowane łącznie na %1 i %2, predykcja %3 (cel %4; wejścia %5; ziarno 1): GNNMCI(1,N) nie dopasowano: %6</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Modular case: %1</source>
        <translation>Przypadek modułowy: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The modules&apos; tests of the thermal study cannot be used (%1); the modules are identified on their own tests.</source>
        <translation>Nie można użyć testów modułów z badania termicznego (%1); moduły są identyfikowane na własnych testach.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Modules identified on %1; the others kept their models. The modules&apos; sum: RMSE %2%3 on %4.</source>
        <translation>Moduły zidentyfikowane na %1; pozostałe zachowały swoje modele. Suma modułów: RMSE %2%3 na %4.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the tests of the thermal study</source>
        <translation>testach badania termicznego</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Identify module %1 again on %2</source>
        <translation>Zidentyfikuj moduł %1 ponownie na %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Identifying…</source>
        <translation>Identyfikacja…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Reading %1…</source>
        <translation>Odczyt %1…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Identifying on %1…</source>
        <translation>Identyfikacja na %1…</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Saved %1 to %2.</source>
        <translation>Zapisano %1 w %2.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot save the module models: %1</source>
        <translation>Nie można zapisać modeli modułów: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Identify %1 again</source>
        <translation>Zidentyfikuj %1 ponownie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The test to identify module %1 on (a new test of its drive; now %2). The other modules keep their models.</source>
        <translation>Test, na którym zidentyfikować moduł %1 (nowy test jego napędu; teraz %2). Pozostałe moduły zachowują swoje modele.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Save module models to</source>
        <translation>Zapisz modele modułów w</translation>
    </message>
    <message>
        <location line="-161"/>
        <source>Fitted on %1 and %2 together, predicting %3 (target %4; inputs %5; seed 1): GNNMCI(1,N) reduces the combined test&apos;s error by %6 %.</source>
        <translation>Dopasowano łącznie na %1 i %2, prognoza dla %3 (wielkość docelowa %4; wejścia %5; ziarno 1): GNNMCI(1,N) zmniejsza błąd testu łączonego o %6 %.</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalTrendView</name>
    <message>
        <location filename="../widgets/thermal/thermaltrendview.cpp" line="+125"/>
        <source>Channels shown in the chart: tick a group to show all of it</source>
        <translation>Kanały pokazane na wykresie: zaznaczona grupa pokazuje wszystkie swoje kanały</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Channels</source>
        <translation>Kanały</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Show or hide all %1</source>
        <translation>Pokaż lub ukryj wszystkie: %1</translation>
    </message>
</context>
<context>
    <name>metrofit::ThermalVerdict</name>
    <message>
        <location filename="../widgets/thermal/thermalverdict.cpp" line="+19"/>
        <source>usable</source>
        <translation>użyteczny</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not usable</source>
        <translation>nieużyteczny</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>its prediction diverges on the held-out rows</source>
        <translation>jego prognoza rozbiega się na odłożonych wierszach</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>E = %1 on the held-out rows, below %2: it predicts worse than the mean of the error</source>
        <translation>E = %1 na odłożonych wierszach, poniżej %2: przewiduje gorzej niż średnia błędu</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>R = %1 on the held-out rows, below %2: it hardly follows the error</source>
        <translation>R = %1 na odłożonych wierszach, poniżej %2: ledwo nadąża za błędem</translation>
    </message>
</context>
<context>
    <name>metrofit::core</name>
    <message>
        <location filename="../widgets/diagnose/coretexts.cpp" line="+20"/>
        <source>n/a</source>
        <translation>b.d.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accepted: </source>
        <translation>przyjęty: </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; passed, but %1 explains more</source>
        <translation>; spełnia kryteria, ale %1 wyjaśnia więcej</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>anulowano</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped by the observer after round %1</source>
        <translation>zatrzymane przez obserwatora po rundzie %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time (min)</source>
        <translation>czas (min)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>radial residual (mm)</source>
        <translation>residuum promieniowe (mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>too few fit rows (%1) for %2 coefficients</source>
        <translation>za mało wierszy dopasowania (%1) dla %2 współczynników</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>column &apos;%1&apos; is constant on the fit rows</source>
        <translation>kolumna „%1” jest stała w wierszach dopasowania</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the columns are linearly dependent on the fit rows</source>
        <translation>kolumny są liniowo zależne w wierszach dopasowania</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drift %1 +- %2%3/min</source>
        <translation>dryf %1 ± %2%3/min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>coefficient %1 +- %2%3 per unit</source>
        <translation>współczynnik %1 ± %2%3 na jednostkę</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>coefficient %1 +- %2%3 per %4</source>
        <translation>współczynnik %1 ± %2%3 na %4</translation>
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
        <translation>zadeklarowany model (statyczny, dopasowany do pierwszych %1 z %2 wierszy): %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>noise level (first differences of the fit residual): %1%2</source>
        <translation>poziom szumu (pierwsze różnice residuum dopasowania): %1%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not estimable: %1</source>
        <translation>nie do oszacowania: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>validation rmse %1 -&gt; %2%3 (%4), fit rmse %5 -&gt; %6%3, held-out rmse %7 -&gt; %8%3</source>
        <translation>rmse walidacji %1 → %2%3 (%4), rmse dopasowania %5 → %6%3, rmse danych testowych %7 → %8%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>validation rmse %1 -&gt; %2%3 (%4), fit rmse %5 -&gt; %6%3, held-out rmse %7 -&gt; %8%3, %9</source>
        <translation>rmse walidacji %1 → %2%3 (%4), rmse dopasowania %5 → %6%3, rmse danych testowych %7 → %8%3, %9</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; rejected: validation error worse</source>
        <translation>; odrzucony: błąd walidacji większy</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: validation gain below %1 %</source>
        <translation>; odrzucony: zysk w walidacji poniżej %1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: explains %1%2, below %3 x the noise level %4%2</source>
        <translation>; odrzucony: wyjaśnia %1%2, poniżej %3 × poziom szumu %4%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: no in-sample evidence (fit dBIC %1 &gt;= 0)</source>
        <translation>; odrzucony: brak dowodów w danych dopasowania (dBIC dopasowania %1 ≥ 0)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>accepted together with %1: validation rmse %2 -&gt; %3%4 (%5), fit rmse %6 -&gt; %7%4, held-out rmse %8 -&gt; %9%4, %10</source>
        <translation>przyjęty razem z %1: rmse walidacji %2 → %3%4 (%5), rmse dopasowania %6 → %7%4, rmse danych testowych %8 → %9%4, %10</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>; rejected: the validation folds cannot fit it</source>
        <translation>; odrzucony: nie da się go dopasować w foldach walidacji</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>effects chosen on the fit rows by blocked forward validation (%1 folds, validation rmse %2%3); the held-out rows only report the error</source>
        <translation>efekty wybrane na wierszach dopasowania przez blokową walidację w przód (%1 foldy, rmse walidacji %2%3); wiersze testowe podają tylko błąd</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>%1 gross errors excluded before the fit (robust z above %2):</source>
        <translation>%1 błędów grubych wykluczonych przed dopasowaniem (odporne z powyżej %2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> row %1 (%2%3)</source>
        <translation> wiersz %1 (%2%3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: the generic %1 validates better (%2 against %3%4)</source>
        <translation>; odrzucony: efekt ogólny %1 lepiej się waliduje (%2 wobec %3%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; not taken: the generic %1 validates better (%2 against %3%4)</source>
        <translation>; nie przyjęty: efekt ogólny %1 lepiej się waliduje (%2 wobec %3%4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: the residual still depends on %1 after it (%2, p = %3)</source>
        <translation>; odrzucony: reszta nadal zależy od %1 po jego dodaniu (%2, p = %3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: the fit rows do not determine tau (standard error above half of it)</source>
        <translation>; odrzucony: wiersze dopasowania nie wyznaczają tau (błąd standardowy powyżej połowy)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>declared model %1 of %2 (fitted on the first %3 of %4 rows as thermal fit does; alone: fit rmse %5, held-out rmse %6%7); the loop fits the target on its prediction (coefficient %8) and the candidate effects</source>
        <translation>zadeklarowany model %1 z %2 (dopasowany do pierwszych %3 z %4 wierszy jak w thermal fit; sam: rmse dopasowania %5, rmse danych testowych %6%7); pętla dopasowuje wielkość docelową do jego predykcji (współczynnik %8) i efektów kandydujących</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>residual</source>
        <translation>residuum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>residual (%1)</source>
        <translation>residuum (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>path angle (deg)</source>
        <translation>kąt na torze (stopnie)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared model: origin (%1, %2) um, x axis %3 deg, y axis %4 deg, squareness %5 deg</source>
        <translation>zadeklarowany model: początek (%1; %2) µm, oś x %3°, oś y %4°, prostopadłość %5°</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not estimable: no period range to search on this path</source>
        <translation>nie do oszacowania: brak zakresu okresów do przeszukania na tym torze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not estimable from this path: its parameters are not observable together with the declared ones</source>
        <translation>nie do oszacowania z tego toru: jego parametry nie są obserwowalne razem z zadeklarowanymi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>backlash x %1 +- %2 um, y %3 +- %4 um</source>
        <translation>luz zwrotny x %1 ± %2 µm, y %3 ± %4 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scale x %1 +- %2 ppm, y %3 +- %4 ppm</source>
        <translation>skala x %1 ± %2 ppm, y %3 ± %4 ppm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>servo lag tau %1 +- %2 s at %3 mm/min (%4 um)</source>
        <translation>opóźnienie serwa τ %1 ± %2 s przy %3 mm/min (%4 µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cyclic on %1: period %2 +- %3 mm, amplitude %4 +- %5 um</source>
        <translation>cykliczny na %1: okres %2 ± %3 mm, amplituda %4 ± %5 µm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rmse %1 -&gt; %2 um (%3 %), dBIC %4, %5</source>
        <translation>rmse %1 → %2 µm (%3 %), dBIC %4, %5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: dBIC above -%1</source>
        <translation>; odrzucony: dBIC powyżej -%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; rejected: rmse gain below %1 %</source>
        <translation>; odrzucony: zysk rmse poniżej %1 %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>declared model: constant errors of the %1 setup data through the relation graph, least squares over %2 rows of %3 parts; rank %4 of %5</source>
        <translation>zadeklarowany model: stałe błędy danych ustawczych (%1) poprzez graf relacji, najmniejsze kwadraty dla %2 wierszy z %3 przedmiotów; rząd %4 z %5</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> (rank deficient: minimum-norm solution)</source>
        <translation> (niepełny rząd: rozwiązanie o minimalnej normie)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared fit (minimum norm), setup errors mm:</source>
        <translation>zadeklarowane dopasowanie (minimalna norma), błędy ustawcze mm:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> %1=%2</source>
        <translation> %1=%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not identifiable: %1 (one part only?)</source>
        <translation>nieidentyfikowalny: %1 (tylko jeden przedmiot?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not identifiable: %1 (time does not vary?)</source>
        <translation>nieidentyfikowalny: %1 (czas się nie zmienia?)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 +- %2 mm/part (t = %3); </source>
        <translation>%1 ± %2 mm/przedmiot (t = %3); </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 +- %2 mm/min (t = %3); </source>
        <translation>%1 ± %2 mm/min (t = %3); </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part</source>
        <translation>przedmiot</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>apparent error of %1 (mm)</source>
        <translation>pozorny błąd %1 (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; preferred to %1 (its dBIC is %2 lower, below the threshold: the data cannot tell them apart)</source>
        <translation>; preferowany względem %1 (jego dBIC jest niższe o %2, poniżej progu: dane nie pozwalają ich rozróżnić)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>; indistinguishable from %1 with these data</source>
        <translation>; nieodróżnialny od %1 przy tych danych</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>distance from the centroid (mm)</source>
        <translation>odległość od środka ciężkości (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deviation along the normal (mm)</source>
        <translation>odchyłka wzdłuż normalnej (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>surface</source>
        <translation>powierzchnia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>polar angle (deg)</source>
        <translation>kąt biegunowy (stopnie)</translation>
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
        <translation>zadeklarowany model: sztywne położenie p = R q + t dopasowane do %1, punkty: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the deviations along the nominal normals</source>
        <translation>odchyłek wzdłuż normalnych nominalnych</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the in-plane residuals (planar, position-only)</source>
        <translation>residuów w płaszczyźnie (płaskie, tylko położenie)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the residual vectors (position-only)</source>
        <translation>wektorów residuów (tylko położenie)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>declared fit: rotation_deg [%1, %2, %3], translation_mm [%4, %5, %6]</source>
        <translation>zadeklarowane dopasowanie: obrót w stopniach [%1; %2; %3], przesunięcie w mm [%4; %5; %6]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not identifiable: %1 (the rigid posture explains it with these points)</source>
        <translation>nieidentyfikowalny: %1 (sztywne położenie wyjaśnia go przy tych punktach)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1; %2</source>
        <translation>%1; %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; indistinguishable from %1 with these points</source>
        <translation>; nieodróżnialny od %1 przy tych punktach</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dBIC = %1 &lt; -%2, rmse %3 -&gt; %4 %5 (-%6 %)</source>
        <translation>dBIC = %1 &lt; -%2, rmse %3 → %4 %5 (-%6 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dBIC = %1 not below -%2, rmse %3 -&gt; %4 %5 (-%6 %)</source>
        <translation>dBIC = %1 nie poniżej -%2, rmse %3 → %4 %5 (-%6 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dBIC = %1 &lt; -%2, rmse %3 -&gt; %4 %5 (-%6 %, below the relevant %7 %)</source>
        <translation>dBIC = %1 &lt; -%2, rmse %3 → %4 %5 (-%6 %, poniżej istotnych %7 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dBIC = %1 &lt; -%2, rmse %3 -&gt; %4 %5 (-%6 %, below the relevant %7 %5)</source>
        <translation>dBIC = %1 &lt; -%2, rmse %3 → %4 %5 (-%6 %, poniżej istotnych %7 %5)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>absorbed by the declared model</source>
        <translation>wchłonięty przez zadeklarowany model</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>its parameters are not separable with these data</source>
        <translation>jego parametry nie są rozdzielne przy tych danych</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>too few data for the parameters</source>
        <translation>za mało danych dla parametrów</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>linear</source>
        <translation>liniowa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>smooth</source>
        <translation>gładka</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+98"/>
        <source>step</source>
        <translation>skok</translation>
    </message>
    <message>
        <location line="-97"/>
        <source>periodic</source>
        <translation>okresowa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per level</source>
        <translation>na poziom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spike</source>
        <translation>impuls</translation>
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
        <translation>za mało obserwacji (%1), by zbadać residuum</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>white: no test finds structure at the %1 % family-wise level (%2 tests)</source>
        <translation>białe: żaden test nie znajduje struktury na poziomie %1 % dla całej rodziny (testów: %2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not white: still depends on </source>
        <translation>nie białe: wciąż zależy od zmiennych: </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2, %3 % of the residual variance)</source>
        <translation>%1 (%2, %3 % wariancji residuum)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> and %1 more</source>
        <translation> i kolejne (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not white: serially correlated in %1 order (Ljung-Box p = %2)</source>
        <translation>nie białe: skorelowane szeregowo w kolejności %1 (Ljung-Box p = %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 in %2, rms %3%4, range %5%4</source>
        <translation>%1 względem %2, rms %3%4, rozstęp %5%4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, step %1%2 at %3</source>
        <translation>, skok %1%2 przy %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, strongest harmonic %1 (amplitude %2%3)</source>
        <translation>, najsilniejsza harmoniczna %1 (amplituda %2%3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, period %1, amplitude %2%3</source>
        <translation>, okres %1, amplituda %2%3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 gross errors excluded before the fit (robust z above the outlier threshold):</source>
        <translation>Błędy grube wykluczone przed dopasowaniem (%1; odporne z powyżej progu wartości odstających):</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> row %1 (%2 um)</source>
        <translation> wiersz %1 (%2 µm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> row %1 (part %2, %3, %4 mm)</source>
        <translation> wiersz %1 (przedmiot %2, %3, %4 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> point %1 (row %2, %3 mm)</source>
        <translation> punkt %1 (wiersz %2, %3 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; </source>
        <translation>; </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not identifiable: %1</source>
        <translation>nieidentyfikowalny: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rejected: does not explain what it was chosen for; without it the generic effects explain the data as well (BIC %1 without, %2 with, needed %3 lower)</source>
        <translation>odrzucony: nie wyjaśnia tego, do czego został wybrany; bez niego efekty ogólne wyjaśniają dane równie dobrze (BIC %1 bez, %2 z nim, potrzebne o %3 niżej)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>samples since an axis reversed (signed, log scale)</source>
        <translation>próbki od nawrotu osi (ze znakiem, skala logarytmiczna)</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>data row</source>
        <translation>wiersz danych</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dimension</source>
        <translation>wymiar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>loop direction</source>
        <translation>kierunek obiegu</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>part number (%1)</source>
        <translation>numer przedmiotu (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>position along surface %1 (mm)</source>
        <translation>położenie wzdłuż powierzchni %1 (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>normal x</source>
        <translation>normalna x</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>normal y</source>
        <translation>normalna y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>normal z</source>
        <translation>normalna z</translation>
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
        <translation>zbieżny</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>budget exhausted</source>
        <translation>budżet wyczerpany</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>iteration limit</source>
        <translation>limit iteracji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>niepowodzenie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown</source>
        <translation>nieznany</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no nominal value given: nothing to compensate against</source>
        <translation>nie podano wartości nominalnej: brak odniesienia do kompensacji</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroup %1 beyond the X-bar limits</source>
        <translation>podgrupa %1 poza granicami karty X-średnie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroups %1 beyond the X-bar limits</source>
        <translation>podgrupy %1 poza granicami karty X-średnie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroup %1 beyond the R limits</source>
        <translation>podgrupa %1 poza granicami karty R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>subgroups %1 beyond the R limits</source>
        <translation>podgrupy %1 poza granicami karty R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; subgroup %1 beyond the R limits</source>
        <translation>; podgrupa %1 poza granicami karty R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; subgroups %1 beyond the R limits</source>
        <translation>; podgrupy %1 poza granicami karty R</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not compensated: the process is out of control (%1); remove the special causes first, a correction would chase them</source>
        <translation>bez kompensacji: proces nie jest pod kontrolą (%1); najpierw usuń przyczyny specjalne, korekta goniłaby je</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not compensated: the systematic error %1 is within its interval +-%2 (k = %3): random scatter, not a systematic error</source>
        <translation>bez kompensacji: błąd systematyczny %1 mieści się w swoim przedziale ±%2 (k = %3): rozrzut losowy, nie błąd systematyczny</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not compensated: the systematic error %1 is below the smallest correction %2</source>
        <translation>bez kompensacji: błąd systematyczny %1 jest mniejszy niż najmniejsza korekta %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>compensate %1: the systematic error (nominal - mean, Eq. 20) is beyond its interval +-%2 (k = %3) and the process is in control (%4 subgroups of %5)</source>
        <translation>kompensuj %1: błąd systematyczny (nominał − średnia, równ. 20) wykracza poza swój przedział ±%2 (k = %3), a proces jest pod kontrolą (%4 podgrup po %5)</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+11"/>
        <source>time constant</source>
        <translation>stała czasowa</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>coefficient</source>
        <translation>współczynnik</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+12"/>
        <source>drift rate</source>
        <translation>szybkość dryfu</translation>
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
        <translation>oś</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>period</source>
        <translation>okres</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+16"/>
        <source>amplitude</source>
        <translation>amplituda</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>phase</source>
        <translation>faza</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>lag</source>
        <translation>opóźnienie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>change per part</source>
        <translation>zmiana na przedmiot</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>scale</source>
        <translation>skala</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>offset</source>
        <translation>przesunięcie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>angle</source>
        <translation>kąt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>form</source>
        <translation>postać</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms</source>
        <translation>rms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>range</source>
        <translation>rozstęp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at</source>
        <translation>przy</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>harmonic</source>
        <translation>harmoniczna</translation>
    </message>
</context>
</TS>
