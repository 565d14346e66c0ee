<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it_IT" sourcelanguage="en_US">
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+18"/>
        <source>Structural dynamics workbench</source>
        <translation>Banco di lavoro per la dinamica strutturale</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Project file to open</source>
        <translation>File di progetto da aprire</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save a screenshot of the window to FILE and quit.</source>
        <translation>Salva un&apos;immagine della finestra in FILE ed esci.</translation>
    </message>
</context>
<context>
    <name>mozzi::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+240"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New Project...</source>
        <translation>&amp;Nuovo progetto...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open Project...</source>
        <translation>&amp;Apri progetto...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open &amp;Recent</source>
        <translation>Apri &amp;recenti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear List</source>
        <translation>Svuota elenco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Project &amp;As...</source>
        <translation>Salva progetto &amp;come...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Close Project</source>
        <translation>&amp;Chiudi progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Import</source>
        <translation>&amp;Importa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export</source>
        <translation>&amp;Esporta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Work Area as &amp;Image...</source>
        <translation>Area di lavoro come &amp;immagine...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Universal File (UFF)...</source>
        <translation>File &amp;Universal (UFF)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+64"/>
        <source>Project</source>
        <translation>Progetto</translation>
    </message>
    <message>
        <location line="-63"/>
        <source>Properties</source>
        <translation>Proprietà</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Log</source>
        <translation>Registro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset Layout</source>
        <translation>&amp;Ripristina disposizione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Language</source>
        <translation>&amp;Lingua</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Tools</source>
        <translation>&amp;Strumenti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Create &amp;Demo Project...</source>
        <translation>Crea progetto &amp;dimostrativo...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check Project &amp;Integrity</source>
        <translation>Verifica &amp;integrità del progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Model vs Test...</source>
        <translation>&amp;Modello contro prova...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diagnose where a model and a test disagree and which unmodelled effect explains it</source>
        <translation>Diagnostica dove modello e prova non concordano e quale effetto non modellato lo spiega</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+300"/>
        <source>Model vs Test</source>
        <translation>Modello contro prova</translation>
    </message>
    <message>
        <location line="-299"/>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About Mozzi</source>
        <translation>&amp;Informazioni su Mozzi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About &amp;Qt</source>
        <translation>Informazioni su &amp;Qt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overview</source>
        <translation>Panoramica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3-D View</source>
        <translation>Vista 3D</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+120"/>
        <source>Item</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <location line="-120"/>
        <location line="+121"/>
        <source>Count</source>
        <translation>Numero</translation>
    </message>
    <message>
        <location line="-120"/>
        <source>Property</source>
        <translation>Proprietà</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Valore</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Mozzi</source>
        <translation>Mozzi</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 - Mozzi</source>
        <translation>%1 - Mozzi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> [read-only]</source>
        <translation> [sola lettura]</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+269"/>
        <source>Could not read the project.</source>
        <translation>Impossibile leggere il progetto.</translation>
    </message>
    <message>
        <location line="-262"/>
        <source>Specimens</source>
        <translation>Provini</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>FRF sets</source>
        <translation>Insiemi di FRF</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Modal results</source>
        <translation>Risultati modali</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Data</source>
        <translation>Dati</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>File</source>
        <translation>File</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Access</source>
        <translation>Accesso</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>read-only: %1</source>
        <translation>sola lettura: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read-write</source>
        <translation>lettura e scrittura</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+7"/>
        <location line="+5"/>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Description</source>
        <translation>Descrizione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mesh</source>
        <translation>Mesh</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 nodes, %2 lines</source>
        <translation>%1 nodi, %2 linee</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Source</source>
        <translation>Origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency lines</source>
        <translation>Righe in frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response/reference pairs</source>
        <translation>Coppie risposta/riferimento</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Method</source>
        <translation>Metodo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Band</source>
        <translation>Banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modes</source>
        <translation>Modi</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Where: %1</source>
        <translation>Dove: %1</translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+178"/>
        <source>Open Project</source>
        <translation>Apri progetto</translation>
    </message>
    <message>
        <location line="-178"/>
        <source>Could not open %1.</source>
        <translation>Impossibile aprire %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Opened %1</source>
        <translation>Aperto %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read-only: %1</source>
        <translation>Sola lettura: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+160"/>
        <source>New Project</source>
        <translation>Nuovo progetto</translation>
    </message>
    <message>
        <location line="-160"/>
        <source>Could not create %1.</source>
        <translation>Impossibile creare %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Created %1</source>
        <translation>Creato %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Demo Project</source>
        <translation>Progetto dimostrativo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Could not create the demo project %1.</source>
        <translation>Impossibile creare il progetto dimostrativo %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Created demo project %1</source>
        <translation>Creato il progetto dimostrativo %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+152"/>
        <source>Save Project As</source>
        <translation>Salva progetto come</translation>
    </message>
    <message>
        <location line="-152"/>
        <source>Could not save the project as %1.</source>
        <translation>Impossibile salvare il progetto come %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Saved a copy as %1 and opened it</source>
        <translation>Salvata una copia come %1 e aperta</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export Image</source>
        <translation>Esporta immagine</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Could not write %1.</source>
        <translation>Impossibile scrivere %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Exported the work area to %1</source>
        <translation>Area di lavoro esportata in %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot show the mesh: %1</source>
        <translation>Impossibile mostrare la mesh: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot place the mesh: %1</source>
        <translation>Impossibile posizionare la mesh: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n trace line segment(s) name nodes the mesh does not have and are not drawn</source>
        <translation>
            <numerusform>%n segmento di linea di traccia cita nodi assenti dalla mesh e non viene disegnato</numerusform>
            <numerusform>%n segmenti di linea di traccia citano nodi assenti dalla mesh e non vengono disegnati</numerusform>
        </translation>
    </message>
    <message>
        <location line="+26"/>
        <source>FRF Set</source>
        <translation>Insieme di FRF</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Could not read the FRF set.</source>
        <translation>Impossibile leggere l&apos;insieme di FRF.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>FRF: %1</source>
        <translation>FRF: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+1"/>
        <source>Model vs test: %1</source>
        <translation>Modello contro prova: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+9"/>
        <location line="+7"/>
        <source>Import</source>
        <translation>Importa</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Could not add a specimen for %1.</source>
        <translation>Impossibile aggiungere un provino per %1.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Could not import %1; the project is unchanged.</source>
        <translation>Impossibile importare %1; il progetto non è stato modificato.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Imported %1: %2 nodes, %3 lines, %4 FRFs, %5 modes</source>
        <translation>Importato %1: %2 nodi, %3 linee, %4 FRF, %5 modi</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Import Universal File</source>
        <translation>Importa file Universal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Universal files (*.uff *.unv);;All files (*)</source>
        <translation>File Universal (*.uff *.unv);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+13"/>
        <location line="+14"/>
        <source>Mozzi projects (*.mozzi)</source>
        <translation>Progetti Mozzi (*.mozzi)</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>Mozzi projects (*.mozzi);;All files (*)</source>
        <translation>Progetti Mozzi (*.mozzi);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Export Work Area</source>
        <translation>Esporta area di lavoro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNG images (*.png);;JPEG images (*.jpg)</source>
        <translation>Immagini PNG (*.png);;Immagini JPEG (*.jpg)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Create Demo Project</source>
        <translation>Crea progetto dimostrativo</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Check Project Integrity</source>
        <translation>Verifica integrità del progetto</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The project failed its integrity check.</source>
        <translation>Il progetto non ha superato la verifica di integrità.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Integrity check passed: %1</source>
        <translation>Verifica di integrità superata: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Integrity check passed</source>
        <translation>Verifica di integrità superata</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;h3&gt;Mozzi %1&lt;/h3&gt;&lt;p&gt;Structural dynamics workbench for two-wheeled-vehicle components: impact-hammer campaigns, stiffness rigs, tyre tests, modal and twist-axis identification, stability models.&lt;/p&gt;&lt;p&gt;Linked libraries:&lt;/p&gt;&lt;ul&gt;</source>
        <translation>&lt;h3&gt;Mozzi %1&lt;/h3&gt;&lt;p&gt;Banco di lavoro per la dinamica strutturale dei componenti dei veicoli a due ruote: campagne con martello strumentato, banchi di rigidezza, prove pneumatici, identificazione modale e degli assi di torsione, modelli di stabilità.&lt;/p&gt;&lt;p&gt;Librerie collegate:&lt;/p&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>About Mozzi</source>
        <translation>Informazioni su Mozzi</translation>
    </message>
</context>
<context>
    <name>mozzi::views::FrfPlot</name>
    <message>
        <location filename="../views/plots/frf_plot.cpp" line="+128"/>
        <source>Unwrap phase</source>
        <translation>Fase continua</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response / reference</source>
        <translation>Risposta / riferimento</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>receptance</source>
        <translation>recettanza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mobility</source>
        <translation>mobilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accelerance</source>
        <translation>inertanza</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnitude [dB]</source>
        <translation>Modulo [dB]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>|H| %1 [dB]</source>
        <translation>|H| %1 [dB]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phase [deg]</source>
        <translation>Fase [gradi]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coherence</source>
        <translation>Coerenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ModelTestView</name>
    <message>
        <location filename="../views/gap/model_test_view.cpp" line="+226"/>
        <source>Export Diagnosis Report</source>
        <translation>Esporta rapporto di diagnosi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HTML report (*.html)</source>
        <translation>Rapporto HTML (*.html)</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Choose Model</source>
        <translation>Scegli il modello</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Models (*.json *.uff *.unv);;All files (*)</source>
        <translation>Modelli (*.json *.uff *.unv);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Choose Test Data</source>
        <translation>Scegli i dati di prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test data (*.uff *.unv *.csv *.json);;All files (*)</source>
        <translation>Dati di prova (*.uff *.unv *.csv *.json);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Choose a model file and a test file first.</source>
        <translation>Scegli prima un file di modello e un file di prova.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cannot use these files: %1</source>
        <translation>Impossibile usare questi file: %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 data, %2 residuals, %3 candidate effects at their locations.</source>
        <translation>Dati %1, %2 residui, %3 effetti candidati nelle loro posizioni.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Tick at least one candidate effect.</source>
        <translation>Seleziona almeno un effetto candidato.</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Diagnosing...</source>
        <translation>Diagnosi in corso...</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Diagnosis done.</source>
        <translation>Diagnosi completata.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The diagnosis stopped: %1</source>
        <translation>La diagnosi si è interrotta: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+164"/>
        <location line="+99"/>
        <source>Verdict: %1</source>
        <translation>Verdetto: %1</translation>
    </message>
    <message>
        <location line="-227"/>
        <location line="+134"/>
        <source>Item</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <location line="-134"/>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Significant</source>
        <translation>Significativo</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>yes</source>
        <translation>sì</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Effect</source>
        <translation>Effetto</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Location</source>
        <translation>Posizione</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Size ± standard error</source>
        <translation>Entità ± errore standard</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Likelihood ratio</source>
        <translation>Rapporto di verosimiglianza</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Threshold</source>
        <translation>Soglia</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Held-out gain</source>
        <translation>Miglioramento sui dati esclusi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shrink</source>
        <translation>Riduzione</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>(not identifiable)</source>
        <translation>(non identificabile)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>model + %1</source>
        <translation>modello + %1</translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+112"/>
        <source>model + best effect</source>
        <translation>modello + effetto migliore</translation>
    </message>
    <message>
        <location line="-102"/>
        <location line="+1"/>
        <source>Model vs test</source>
        <translation>Modello contro prova</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+76"/>
        <source>Model</source>
        <translation>Modello</translation>
    </message>
    <message>
        <location line="-76"/>
        <location line="+78"/>
        <source>Test</source>
        <translation>Prova</translation>
    </message>
    <message>
        <location line="-72"/>
        <source>Gap before</source>
        <translation>Scarto iniziale</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gap</source>
        <translation>Scarto</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+79"/>
        <source>Ranked effects</source>
        <translation>Effetti in classifica</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>Measured and model, before and after</source>
        <translation>Misura e modello, prima e dopo</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Nothing to export: run the diagnosis first.</source>
        <translation>Niente da esportare: esegui prima la diagnosi.</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+8"/>
        <source>Cannot write %1: %2</source>
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>mozzi-model/1 JSON, UFF 55 modes, tyre or stability gap file</source>
        <translation>JSON mozzi-model/1, modi UFF 55, file di scarto pneumatico o stabilità</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UFF 58 FRFs, identified modes, relaxation lengths or stability frequencies</source>
        <translation>FRF UFF 58, modi identificati, lunghezze di rilassamento o frequenze di stabilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>Browse...</source>
        <translation>Sfoglia...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Band</source>
        <translation>Banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lowest frequency used (0 = from the first line)</source>
        <translation>Frequenza minima usata (0 = dalla prima riga)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest frequency used (0 = to the last line)</source>
        <translation>Frequenza massima usata (0 = fino all&apos;ultima riga)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bootstrap samples</source>
        <translation>Campioni bootstrap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated data sets that calibrate the false-attribution threshold</source>
        <translation>Insiemi di dati simulati che tarano la soglia delle false attribuzioni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Multistarts</source>
        <translation>Partenze multiple</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Starting points of every nonlinear fit (more are slower and safer)</source>
        <translation>Punti di partenza di ogni stima non lineare (di più: più lento e più sicuro)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Candidate effects</source>
        <translation>Effetti candidati</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load</source>
        <translation>Carica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run Diagnosis</source>
        <translation>Esegui diagnosi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Annulla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export Report...</source>
        <translation>Esporta rapporto...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where</source>
        <translation>Dove</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Overlay</source>
        <translation>Sovrapposizione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured</source>
        <translation>misura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>model</source>
        <translation>modello</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No diagnosis yet</source>
        <translation>Nessuna diagnosi</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ProjectOverview</name>
    <message>
        <location filename="../views/panels/project_overview.cpp" line="+70"/>
        <source>Specimen</source>
        <translation>Provino</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Description</source>
        <translation>Descrizione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No project open</source>
        <translation>Nessun progetto aperto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Create a project with File &gt; New, open one with File &gt; Open, or try the demo with Tools &gt; Create Demo Project.</source>
        <translation>Crea un progetto con File &gt; Nuovo, aprine uno con File &gt; Apri, oppure prova la dimostrazione con Strumenti &gt; Crea progetto dimostrativo.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>File: %1
Schema version %2, created %3 by Mozzi %4</source>
        <translation>File: %1
Versione dello schema %2, creato il %3 da Mozzi %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Opened read-only: %1</source>
        <translation>Aperto in sola lettura: %1</translation>
    </message>
</context>
</TS>
